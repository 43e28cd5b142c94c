// Table of contents: setup · input (keys, mouse: drag, cut, pins, recording) · drawing (runs
// side by side, their labels) · main loop.
#include "app/demo_window.h"

#include <SDL.h>
#include <imgui.h>
#include <imgui_impl_sdl.h>
#include <imgui_impl_sdlrenderer.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <glm/geometric.hpp>
#include <sstream>
#include <string_view>

#include "app/atomic_file.h"
#include "app/camera_framing.h"
#include "app/captures_folder.h"
#include "app/control_panel.h"
#include "app/demo_state.h"
#include "app/hand_tools.h"
#include "app/headless_runner.h"
#include "app/obj_export.h"
#include "app/screen_layout.h"
#include "app/screenshot_names.h"
#include "app/session_record.h"
#include "app/side_by_side.h"
#include "app/state_dump.h"
#include "app/status_overlay.h"
#include "app/status_text.h"
#include "app/window_state_file.h"
#include "raster/png_writer.h"
#include "sim/core/energy.h"

namespace weft::app {
namespace {

double now_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// weft draws every pixel of the 3D view itself: the SDL renderer only copies the frame to
// the window and draws the panel. SDL's software renderer does that on the calling thread.
// Under a software OpenGL (Mesa's llvmpipe: Xvfb, a machine without a GPU) the default
// OpenGL renderer's own threads took a quarter of the CPU with the 128² cloth and competed
// with the simulation's two (measured under Xvfb, three runs each: 59.6-60.9 fps with
// OpenGL, 73.7-82.9 fps unpaced in software). The environment still decides
// (SDL_RENDER_DRIVER=opengl, SDL_FRAMEBUFFER_ACCELERATION=1): hints of default priority
// yield to it.
void prefer_software_present() {
    SDL_SetHintWithPriority(SDL_HINT_RENDER_DRIVER, "software", SDL_HINT_DEFAULT);
    SDL_SetHintWithPriority(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0", SDL_HINT_DEFAULT);
}

// With no display SDL falls back to a video driver that draws into memory, and the demo would
// run on with no window until killed. Those drivers count only when asked for by name.
bool has_display() {
    const char* driver = SDL_GetCurrentVideoDriver();
    if (!driver) return false;
    const std::string_view name(driver);
    if (name != "offscreen" && name != "dummy") return true;
    const char* asked = SDL_getenv("SDL_VIDEODRIVER");
    return asked && name == asked;
}

// Seconds a frame should last: the display's refresh period (60 Hz when it does not say).
// A renderer that does not wait for vertical sync would otherwise draw frames nobody sees.
double frame_period(SDL_Window* window) {
    SDL_DisplayMode mode;
    const bool known = SDL_GetWindowDisplayMode(window, &mode) == 0 && mode.refresh_rate > 0;
    return 1.0 / (known ? mode.refresh_rate : 60);
}

struct Window {
    SDL_Window* window = nullptr;
    SDL_Renderer* renderer = nullptr;
    SDL_Texture* texture = nullptr;
    int texture_width = 0, texture_height = 0;
    raster::Framebuffer framebuffer{1, 1};        // the whole view, every run's column
    std::vector<raster::Framebuffer> run_frames;  // one per run when side by side
    // Threads that draw the frame in bands (the simulation has its own for stepping; the
    // two never run at once).
    WorkerPool draw_pool{default_thread_count()};
    bool save_window_next_frame = false;
    int hand_column = 0;  // the column a pull or cut started in: it goes on in its coordinates
    bool panel_folded = false;  // the panel shows only its title bar (as of the last frame)
    WindowLayout layout;        // this frame's: where the panel and the view are
};

// The panel and the view, in the renderer's pixels. The framebuffer is the view's size and
// the camera's viewport is the view: the cloth is never drawn under the panel.
WindowLayout layout_of(const Window& w) {
    int width = 0, height = 0;
    SDL_GetRendererOutputSize(w.renderer, &width, &height);
    return lay_out_window(static_cast<float>(width), static_cast<float>(height), w.panel_folded,
                          ImGui::GetFrameHeight());
}

// The captures folder (captures_folder.h), made if it is not there yet; empty, after saying
// why, if it cannot be.
std::string captures_or_say(DemoState& state) {
    std::string error;
    if (make_captures_folder(state.captures, error)) return state.captures;
    state.say(error, Tone::problem);
    return {};
}

// The window as shown, panel included (Shift+F12).
void save_window_screenshot(DemoState& state, Window& w) {
    int width = 0, height = 0;
    SDL_GetRendererOutputSize(w.renderer, &width, &height);
    if (width < 1 || height < 1) return;
    raster::Framebuffer shot(std::min(width, raster::Framebuffer::max_side),
                             std::min(height, raster::Framebuffer::max_side));
    if (SDL_RenderReadPixels(w.renderer, nullptr, SDL_PIXELFORMAT_ABGR8888, shot.colours().data(),
                             shot.width() * 4) != 0) {
        state.say(std::string("window screenshot failed: ") + SDL_GetError(), Tone::problem);
        return;
    }
    const std::string folder = captures_or_say(state);
    if (folder.empty()) return;
    const std::string path = next_screenshot_path(folder);
    std::string error;
    if (raster::write_png(shot, path, &error)) {
        std::printf("screenshot: %s\n", path.c_str());
        std::fflush(stdout);
    } else {
        state.say("screenshot failed: " + error, Tone::problem);
    }
}

glm::vec2 cursor() {
    int x = 0, y = 0;
    SDL_GetMouseState(&x, &y);
    return {static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f};
}

// ---- input -----------------------------------------------------------------------------

bool over_panel(const Window& w) {
    const glm::vec2 at = cursor();
    const ScreenRect& panel = w.layout.panel;
    return at.x >= panel.x && at.x < panel.right() && at.y >= panel.y &&
           at.y < panel.y + panel.height;
}

void save_screenshot(DemoState& state, const Window& w) {
    const std::string folder = captures_or_say(state);
    if (folder.empty()) return;
    const std::string path = next_screenshot_path(folder);
    std::string error;
    if (raster::write_png(w.framebuffer, path, &error)) {
        std::printf("screenshot: %s\n", path.c_str());
        std::fflush(stdout);
        state.say("saved " + path, Tone::success);
    } else {
        state.say("screenshot failed: " + error, Tone::problem);
    }
}

Columns columns_of(const DemoState& state, const Window& w) {
    return Columns::split(w.layout.view, state.run_count());
}

// The cursor in the coordinates of the column it is over, and that column.
struct Pointer {
    glm::vec2 at;
    ViewSize view;
    int column;
};

Pointer pointer(const DemoState& state, const Window& w) {
    const Columns columns = columns_of(state, w);
    const glm::vec2 window_point = cursor();
    const int column = columns.column_at(window_point.x);
    return {columns.local(window_point, column), columns.view(), column};
}

// The cursor in the coordinates of the column the hand started in.
glm::vec2 hand_point(const DemoState& state, const Window& w) {
    return columns_of(state, w).local(cursor(), w.hand_column);
}

void toggle_recording(DemoState& state) {
    if (!state.recording) {
        state.start_recording();
        state.say("recording: the scene restarted; F5 again stops and saves", Tone::info);
        return;
    }
    const SessionRecord record = state.stop_recording();
    const std::string folder = captures_or_say(state);
    if (folder.empty()) return;
    const std::string path = next_free_path(folder, "weft-session", "toml");
    std::string error;
    if (write_file_atomically(path, session_to_toml(record), false, error))
        state.say("saved the session (" +
                      counted(static_cast<long long>(record.events.size()), "event", "events") +
                      ", " + counted(static_cast<long long>(record.steps), "step", "steps") +
                      ") to " + path + "; weft --replay " + path,
                  Tone::success);
    else
        state.say("could not save the session: " + error, Tone::problem);
}

// O: the cloth as it is now, as Wavefront OBJ beside the screenshots (obj_export.h).
void save_cloth_obj(DemoState& state) {
    const std::string folder = captures_or_say(state);
    if (folder.empty()) return;
    const std::string path = next_free_path(folder, "weft-cloth", "obj");
    std::ostringstream text;
    write_cloth_obj(state.simulation().cloth(), state.simulation().scene().name, text);
    std::string error;
    if (write_file_atomically(path, text.str(), false, error))
        state.say("saved the cloth as a mesh to " + path, Tone::success);
    else
        state.say("could not save the cloth: " + error, Tone::problem);
}

// F9: starts a frame capture into a new folder of the captures folder, or stops the one
// running and says where its frames are and how to make a video of them.
void toggle_frame_capture(DemoState& state) {
    if (state.frame_capture) {
        const FrameCapture& capture = *state.frame_capture;
        state.say("saved " +
                      counted(static_cast<long long>(capture.frames_written()), "frame", "frames") +
                      " to " + capture.folder() + "; scripts/make-video.sh " + capture.folder() +
                      " weft.mp4",
                  Tone::success);
        state.frame_capture.reset();
        return;
    }
    const std::string captures = captures_or_say(state);
    if (captures.empty()) return;
    const std::string folder = next_free_folder(captures, "weft-frames");
    std::string error;
    if (!make_captures_folder(folder, error)) {
        state.say(error, Tone::problem);
        return;
    }
    state.frame_capture.emplace(folder, state.simulation().time());
    state.say("capturing frames to " + folder + " (F9 stops)", Tone::info);
}

// Returns false when the user quits.
bool handle_event(const SDL_Event& event, DemoState& state, Window& w) {
    ImGui_ImplSDL2_ProcessEvent(&event);
    const ImGuiIO& io = ImGui::GetIO();
    if (event.type == SDL_QUIT) return false;
    if (event.type == SDL_KEYDOWN && !io.WantCaptureKeyboard && !event.key.repeat) {
        switch (event.key.keysym.sym) {
            case SDLK_ESCAPE:
                return false;
            case SDLK_p:
                state.toggle_pause();
                break;
            case SDLK_n:
                state.step_once();
                break;
            case SDLK_r:
                state.reset_simulation();
                break;
            case SDLK_F12:
                // Shift+F12: the whole window with the panel, read back after it is drawn.
                if (event.key.keysym.mod & KMOD_SHIFT)
                    w.save_window_next_frame = true;
                else
                    save_screenshot(state, w);
                break;
            case SDLK_o:
                save_cloth_obj(state);
                break;
            case SDLK_F9:
                toggle_frame_capture(state);
                break;
            case SDLK_h:
            case SDLK_F1:
                state.show_help = !state.show_help;
                break;
            case SDLK_HOME: {
                // Frames the cloth's largest piece as it is now, seen from the scene camera's
                // direction.
                const ViewSize view = columns_of(state, w).view();
                state.rig = framed(state.initial_rig, largest_piece_box(state.simulation().cloth()),
                                   float(view.width) / float(view.height));
                break;
            }
            case SDLK_c:
                state.rig = state.initial_rig;
                break;
            case SDLK_t: {
                const Pointer p = pointer(state, w);
                state.toggle_pin(p.at, p.view, p.column);
                break;
            }
            case SDLK_F5:
                toggle_recording(state);
                break;
            case SDLK_u:
                state.release_all_pins();
                break;
            case SDLK_SPACE: {
                const Pointer p = pointer(state, w);
                w.hand_column = p.column;
                state.grab(p.at, p.view, p.column);
                break;
            }
            default:
                break;
        }
    }
    if (event.type == SDL_KEYUP && event.key.keysym.sym == SDLK_SPACE) state.let_go();
    if (event.type == SDL_MOUSEBUTTONDOWN && !io.WantCaptureMouse) {
        const Pointer p = pointer(state, w);
        if (event.button.button != SDL_BUTTON_MIDDLE) w.hand_column = p.column;
        if (event.button.button == SDL_BUTTON_LEFT)
            state.grab(p.at, p.view, p.column);
        else if (event.button.button == SDL_BUTTON_RIGHT)
            state.start_cut(p.at, p.view, p.column);
        else if (event.button.button == SDL_BUTTON_MIDDLE)
            state.toggle_pin(p.at, p.view, p.column);
    }
    if (event.type == SDL_MOUSEBUTTONUP) {
        if (event.button.button == SDL_BUTTON_LEFT) state.let_go();
        if (event.button.button == SDL_BUTTON_RIGHT) state.end_cut();
    }
    if (event.type == SDL_MOUSEMOTION) {
        const ViewSize view = columns_of(state, w).view();
        state.pull(hand_point(state, w), view);
        state.cut_to(hand_point(state, w), view, w.hand_column);
    }
    // Dear ImGui learns that the cursor is over the panel only at the next frame, so a wheel
    // that comes with the cursor's arrival on the panel is judged by where the cursor is.
    if (event.type == SDL_MOUSEWHEEL && !io.WantCaptureMouse && !over_panel(w))
        state.rig.zoom(static_cast<float>(event.wheel.y));
    return true;
}

// Held keys move and turn the camera at rates independent of the frame rate.
void move_camera(DemoState& state, double seconds) {
    if (ImGui::GetIO().WantCaptureKeyboard) return;
    const Uint8* keys = SDL_GetKeyboardState(nullptr);
    const glm::vec3 direction(float(keys[SDL_SCANCODE_D]) - float(keys[SDL_SCANCODE_A]),
                              float(keys[SDL_SCANCODE_E]) - float(keys[SDL_SCANCODE_Q]),
                              float(keys[SDL_SCANCODE_W]) - float(keys[SDL_SCANCODE_S]));
    if (SDL_GetModState() & KMOD_SHIFT) {
        // Shift: the same keys move the first sphere, at 0.5 m/s, level with the camera's
        // heading (W pushes it away from the viewer) and straight up or down.
        const auto& colliders = state.simulation().colliders();
        const auto sphere = std::find_if(colliders.begin(), colliders.end(), [](const Collider& c) {
            return c.type == ColliderType::sphere;
        });
        if (sphere == colliders.end() || direction == glm::vec3(0.0f)) return;
        glm::vec3 ahead = state.rig.forward();
        ahead.y = 0.0f;
        ahead = glm::length(ahead) > 1e-6f ? glm::normalize(ahead) : glm::vec3(0, 0, -1);
        const glm::vec3 right(-ahead.z, 0.0f, ahead.x);
        const glm::vec3 move =
            (direction.x * right + direction.y * glm::vec3(0, 1, 0) + direction.z * ahead) *
            (0.5f * static_cast<float>(seconds));
        state.move_collider(static_cast<std::size_t>(sphere - colliders.begin()),
                            {move.x, move.y, move.z});
        return;
    }
    state.rig.move(direction, 1.0f, static_cast<float>(seconds));  // 1 m/s
    // Arrows move the camera around what it looks at, the way the arrow points.
    const float rightward = float(keys[SDL_SCANCODE_RIGHT]) - float(keys[SDL_SCANCODE_LEFT]);
    const float upward = float(keys[SDL_SCANCODE_UP]) - float(keys[SDL_SCANCODE_DOWN]);
    state.rig.orbit(CameraRig::orbit_rate * rightward, CameraRig::orbit_rate * upward,
                    static_cast<float>(seconds));
}

// ---- drawing --------------------------------------------------------------------------------

bool present_frame(DemoState& state, Window& w) {
    const ScreenRect& view = w.layout.view;
    int width = static_cast<int>(view.width), height = static_cast<int>(view.height);
    if (width < 1 || height < 1 || (SDL_GetWindowFlags(w.window) & SDL_WINDOW_MINIMIZED))
        return false;
    width = std::min(width, raster::Framebuffer::max_side);
    height = std::min(height, raster::Framebuffer::max_side);
    if (width != w.framebuffer.width() || height != w.framebuffer.height())
        w.framebuffer.resize(width, height);
    if (!w.texture || width != w.texture_width || height != w.texture_height) {
        if (w.texture) SDL_DestroyTexture(w.texture);
        // ABGR8888 is R, G, B, A in memory on little-endian machines: raster::Rgba8's order.
        w.texture = SDL_CreateTexture(w.renderer, SDL_PIXELFORMAT_ABGR8888,
                                      SDL_TEXTUREACCESS_STREAMING, width, height);
        w.texture_width = width;
        w.texture_height = height;
    }
    render_runs(w.framebuffer, w.run_frames, state, columns_of(state, w), &w.draw_pool);
    // Into the texture's own memory, rows split between the drawing threads: SDL_UpdateTexture
    // copied the 2.6 MB of a 896 x 720 view on one thread, 1.3-1.5 ms a frame here.
    void* texels = nullptr;
    int pitch = 0;
    if (SDL_LockTexture(w.texture, nullptr, &texels, &pitch) == 0) {
        const raster::Rgba8* rows = w.framebuffer.colours().data();
        const auto row_bytes = static_cast<std::size_t>(width) * sizeof(raster::Rgba8);
        w.draw_pool.parallel_for(
            static_cast<std::size_t>(height), [&](std::size_t begin, std::size_t end) {
                for (std::size_t y = begin; y < end; ++y)
                    std::memcpy(static_cast<char*>(texels) + y * static_cast<std::size_t>(pitch),
                                rows + y * static_cast<std::size_t>(width), row_bytes);
            });
        SDL_UnlockTexture(w.texture);
    } else {
        SDL_UpdateTexture(w.texture, nullptr, w.framebuffer.colours().data(), width * 4);
    }
    const SDL_Rect beside_panel{static_cast<int>(view.x), static_cast<int>(view.y), width, height};
    SDL_RenderCopy(w.renderer, w.texture, nullptr, &beside_panel);
    return true;
}

// Side by side: each column's run named at the top of its column, with its cost and energy,
// wrapped to the column's width so it never reaches into the next column or the panel.
void draw_run_labels(const DemoState& state, const Window& w) {
    if (state.run_count() < 2) return;
    const Columns columns = columns_of(state, w);
    constexpr float margin = 8.0f;
    const float widest = std::max(1.0f, static_cast<float>(columns.width) - 2.0f * margin);
    double copies_seconds = 0.0;
    for (std::size_t r = 1; r < state.runs.size(); ++r) copies_seconds += state.runs[r].seconds;
    for (int run = 0; run < state.run_count(); ++run) {
        const DemoRun& shown = state.runs[static_cast<std::size_t>(run)];
        const Simulation& simulation = shown.simulation;
        // The frame's stepping is measured whole; each copy's is its own.
        const double seconds =
            run == 0 ? state.statistics.sim_seconds - copies_seconds : shown.seconds;
        const int recoveries = shown.recovery.recoveries;
        ImGui::SetNextWindowPos(ImVec2(columns.right_of(run) - margin, columns.top + margin),
                                ImGuiCond_Always, ImVec2(1.0f, 0.0f));
        ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(widest, FLT_MAX));
        ImGui::SetNextWindowBgAlpha(0.55f);
        char name[32];
        std::snprintf(name, sizeof name, "run %d", run);
        ImGui::Begin(name, nullptr,
                     ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                         ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoFocusOnAppearing);
        ImGui::PushTextWrapPos(widest - ImGui::GetStyle().WindowPadding.x);
        ImGui::Text("%s%s",
                    run == 0 ? "main: " : "copy: ", integrator_name(simulation.integrator()));
        ImGui::Text("dt %.3g ms   %.2f ms stepping/frame", simulation.dt() * 1e3, seconds * 1e3);
        ImGui::Text("energy %.5g J   t = %.2f s",
                    measure_energy(simulation.cloth(), simulation.force_field()).total(),
                    simulation.time());
        if (auto solve = linear_solve_text(simulation)) ImGui::TextUnformatted(solve->c_str());
        if (recoveries > 0)
            ImGui::Text("recovered %s", counted(recoveries, "time", "times").c_str());
        ImGui::PopTextWrapPos();
        ImGui::End();
    }
}

}  // namespace

int run_demo_window(const CommandLine& command_line, const char* default_scene_path) {
    // The scene: the file's, or the one a replayed session started from.
    std::optional<SessionRecord> replay;
    std::string path = command_line.scene_path.value_or(default_scene_path);
    std::optional<Scene> scene;
    if (command_line.replay_path) {
        std::string error;
        replay = read_session_file(*command_line.replay_path, error);
        if (!replay) {
            std::fprintf(stderr, "error: %s\n", error.c_str());
            return exit_bad_input;
        }
        path = *command_line.replay_path;
        scene = load_scene_text(replay->scene_toml, path).scene;  // checked when read
    } else {
        scene = load_checked_scene(path, command_line.overrides);
    }
    if (!scene) return exit_bad_input;
    if (auto problem = window_dt_problem(scene->solver.dt)) {
        std::fprintf(stderr, "error: %s: %s\n", path.c_str(), problem->c_str());
        return exit_bad_input;
    }
    for (const CommandLine::Comparison& comparison : command_line.comparisons) {
        if (auto problem = window_dt_problem(comparison.dt)) {
            std::fprintf(stderr, "error: --compare: %s\n", problem->c_str());
            return exit_bad_input;
        }
    }
    prefer_software_present();
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        std::fprintf(stderr, "error: cannot open a window: %s\n", SDL_GetError());
        return exit_bad_input;
    }
    if (!has_display()) {
        std::fprintf(stderr, "error: no display: set DISPLAY, or use --headless\n");
        SDL_Quit();
        return exit_bad_input;
    }
    DemoState state(path, command_line.overrides, *scene);
    state.captures = captures_folder();
    state.main_run().recovery.profiling = true;  // the panel's step profile
    for (const CommandLine::Comparison& comparison : command_line.comparisons)
        state.add_copy(*integrator_from_name(comparison.integrator),
                       comparison.dt > 0.0 ? comparison.dt : scene->solver.dt);
    if (replay) state.start_replay(*replay);
    if (command_line.record_path) state.start_recording();
    Window w;
    const std::string title = "weft - " + scene->name;
    w.window = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                command_line.screenshot_width, command_line.screenshot_height,
                                SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
    if (w.window) w.renderer = SDL_CreateRenderer(w.window, -1, SDL_RENDERER_PRESENTVSYNC);
    if (!w.window || !w.renderer) {
        std::fprintf(stderr, "error: cannot open a window: %s\n", SDL_GetError());
        SDL_Quit();
        return exit_bad_input;
    }
    const double period = frame_period(w.window);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
    ImGui::StyleColorsDark();
    // SDL's software renderer rasterises every triangle ImGui sends, and anti-aliasing adds a
    // fringe of blended triangles to every line and filled shape: with it, the panel took
    // 2.7-3.5 ms a frame to draw on the 64² drape; without it (and without the panel's
    // background, below), 1.5-1.7 ms, time the frame gives back to stepping.
    ImGui::GetStyle().AntiAliasedLines = false;
    ImGui::GetStyle().AntiAliasedFill = false;
    ImGui_ImplSDL2_InitForSDLRenderer(w.window);
    ImGui_ImplSDLRenderer_Init(w.renderer);

    const double started = now_seconds();
    long long frames = 0;
    long long frames_behind = 0;  // frames the step budget cut short (real time not kept)
    double total_sim_seconds = 0.0, total_raster_seconds = 0.0;
    long long total_steps = 0;  // steps of the main run, to tell a step's cost in the window
    double last = now_seconds();
    double seconds_per_step = 0.0;
    // A step's cost is that of the cloths it was measured on: after the panel's grid, the
    // scene picker or side by side changes how many particles step, it is unknown again.
    const auto particles_stepped = [&state] {
        std::size_t particles = 0;
        for (int run = 0; run < state.run_count(); ++run)
            particles += state.run(run).cloth().particle_count();
        return particles;
    };
    std::size_t measured_on = 0;
    double other_seconds = 0.0;  // the last frame's work besides stepping (drawing, panel)
    // What a script driving the window waits on (window_state_file.h).
    const char* state_file = std::getenv("WEFT_WINDOW_STATE");
    bool running = true;
    while (running) {
        w.layout = layout_of(w);
        SDL_Event event;
        while (SDL_PollEvent(&event))
            if (!handle_event(event, state, w)) running = false;
        const double now = now_seconds();
        state.wall_now = now;
        const double elapsed = now - last;
        last = now;
        move_camera(state, elapsed);
        // The camera may move under a held drag.
        state.pull(hand_point(state, w), columns_of(state, w).view());

        // Step: as many fixed steps as keep simulated time with the clock, within budget;
        // while paused, none but the one N or the panel's step button asked for.
        if (particles_stepped() != measured_on) seconds_per_step = 0.0;
        const StepClock::Plan plan = state.plan_frame(elapsed, seconds_per_step, other_seconds);
        const double sim_start = now_seconds();
        const int steps = state.step(plan.steps);
        const double sim_seconds = now_seconds() - sim_start;
        if (state.replay_finished()) {
            if (state.replay_matches())
                state.say("replay finished: the state is bit for bit the recorded one",
                          Tone::success);
            else
                state.say("replay finished: the state DIFFERS from the recorded one",
                          Tone::problem);
            state.stop_replay();
        }
        if (steps > 0) {
            seconds_per_step = sim_seconds / steps;
            measured_on = particles_stepped();
        }
        DemoStatistics& stats = state.statistics;
        stats.steps = steps;
        stats.behind = plan.behind;
        stats.sim_seconds = sim_seconds;
        stats.frame_seconds = elapsed;

        ImGui_ImplSDLRenderer_NewFrame();
        ImGui_ImplSDL2_NewFrame();
        ImGui::NewFrame();
        w.panel_folded = !draw_control_panel(state, w.layout.panel);
        draw_help_overlay(state.show_help);
        draw_status_overlay(state, now, w.layout.view);
        draw_hand_hint(state, w.layout.view);
        draw_run_labels(state, w);
        ImGui::Render();

        // The panel draws no background of its own: it shows this clear colour, the dark
        // style's window background as it used to be blended over the old clear colour.
        SDL_SetRenderDrawColor(w.renderer, 16, 16, 17, 255);
        SDL_RenderClear(w.renderer);
        const double raster_start = now_seconds();
        present_frame(state, w);
        if (state.frame_capture) {
            std::string error;
            if (!state.frame_capture->write_due(w.framebuffer, state.simulation().time(),
                                                state.simulation().dt(), error)) {
                state.say("frame capture stopped: " + error, Tone::problem);
                state.frame_capture.reset();
            }
        }
        stats.raster_seconds = now_seconds() - raster_start;
        state.measure_frame(steps);
        ImGui_ImplSDLRenderer_RenderDrawData(ImGui::GetDrawData());
        ++frames;
        if (plan.behind) ++frames_behind;
        total_sim_seconds += stats.sim_seconds;
        total_steps += steps;
        total_raster_seconds += stats.raster_seconds;
        if (w.save_window_next_frame) {
            save_window_screenshot(state, w);
            w.save_window_next_frame = false;
        }
        SDL_RenderPresent(w.renderer);
        if (state_file && !write_window_state(state_file, frames, state)) {
            std::fprintf(stderr, "error: %s: cannot write the window's state\n", state_file);
            state_file = nullptr;
        }
        other_seconds = now_seconds() - now - sim_seconds;
        // Wait out the rest of the refresh period, in whole milliseconds and a little short
        // (the step clock measures what the frame really took). The software renderer does
        // not wait for vertical sync whatever it is asked; one that does has already waited.
        const double left = period - (now_seconds() - now);
        if (left > 0.002) SDL_Delay(static_cast<Uint32>(1e3 * left) - 1);
    }

    const double seconds = now_seconds() - started;
    if (frames > 0)
        std::printf(
            "%lld frames in %.1f s: %.1f fps, %.2f ms stepping and %.2f ms drawing per frame; "
            "%lld behind real time; %lld steps, %.1f us each\n",
            frames, seconds, static_cast<double>(frames) / seconds,
            1e3 * total_sim_seconds / static_cast<double>(frames),
            1e3 * total_raster_seconds / static_cast<double>(frames), frames_behind, total_steps,
            total_steps > 0 ? 1e6 * total_sim_seconds / static_cast<double>(total_steps) : 0.0);
    if (command_line.record_path && state.recording) {
        std::string error;
        if (write_file_atomically(*command_line.record_path,
                                  session_to_toml(state.stop_recording()), true, error))
            std::printf("session: %s\n", command_line.record_path->c_str());
        else
            std::fprintf(stderr, "error: %s\n", error.c_str());
    }
    if (command_line.dump_path) {
        std::ofstream dump(*command_line.dump_path, std::ios::binary | std::ios::trunc);
        write_state_csv(state.simulation().cloth(), dump);
        if (!dump)
            std::fprintf(stderr, "error: %s: cannot write\n", command_line.dump_path->c_str());
    }
    ImGui_ImplSDLRenderer_Shutdown();
    ImGui_ImplSDL2_Shutdown();
    ImGui::DestroyContext();
    if (w.texture) SDL_DestroyTexture(w.texture);
    SDL_DestroyRenderer(w.renderer);
    SDL_DestroyWindow(w.window);
    SDL_Quit();
    return exit_ok;
}

}  // namespace weft::app
