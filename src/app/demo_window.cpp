// Table of contents: setup · input (keys, mouse: drag, cut, pins) · stepping with recovery ·
// drawing · main loop.
#include "app/demo_window.h"

#include <SDL.h>
#include <imgui.h>
#include <imgui_impl_sdl.h>
#include <imgui_impl_sdlrenderer.h>
#include <chrono>
#include <cstdio>
#include <fstream>

#include "app/control_panel.h"
#include "app/demo_state.h"
#include "app/hand_tools.h"
#include "app/headless_runner.h"
#include "app/screenshot_names.h"
#include "app/state_dump.h"
#include "raster/png_writer.h"
#include "sim/energy.h"

namespace weft::app {
namespace {

double now_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// What the mouse and the space bar are doing to the cloth.
struct Hand {
    bool dragging = false;
    Vec3 anchor{0.0};  // m, the grabbed point when grabbed: the drag plane goes through it
    bool cutting = false;
    glm::vec2 last_cursor{0.0f};
};

void say(DemoState& state, const std::string& message);

struct Window {
    SDL_Window* window = nullptr;
    SDL_Renderer* renderer = nullptr;
    SDL_Texture* texture = nullptr;
    int texture_width = 0, texture_height = 0;
    raster::Framebuffer framebuffer{1, 1};
    // Threads that draw the frame in bands (the simulation has its own for stepping; the
    // two never run at once).
    WorkerPool draw_pool{default_thread_count()};
    bool save_window_next_frame = false;
};

// The window as shown, panel included (Shift+F12).
void save_window_screenshot(DemoState& state, Window& w) {
    int width = 0, height = 0;
    SDL_GetRendererOutputSize(w.renderer, &width, &height);
    if (width < 1 || height < 1) return;
    raster::Framebuffer shot(std::min(width, raster::Framebuffer::max_side),
                             std::min(height, raster::Framebuffer::max_side));
    if (SDL_RenderReadPixels(w.renderer, nullptr, SDL_PIXELFORMAT_ABGR8888, shot.colours().data(),
                             shot.width() * 4) != 0) {
        say(state, std::string("window screenshot failed: ") + SDL_GetError());
        return;
    }
    const std::string path = next_screenshot_path(".");
    std::string error;
    if (raster::write_png(shot, path, &error)) {
        std::printf("screenshot: %s\n", path.c_str());
        std::fflush(stdout);
    } else {
        say(state, "screenshot failed: " + error);
    }
}

glm::vec2 cursor() {
    int x = 0, y = 0;
    SDL_GetMouseState(&x, &y);
    return {static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f};
}

void say(DemoState& state, const std::string& message) {
    state.message = message;
    state.message_until = now_seconds() + 4.0;
    std::fprintf(stderr, "%s\n", message.c_str());
}

// ---- input -----------------------------------------------------------------------------

void start_drag(DemoState& state, const Window& w) {
    auto hit = cloth_under_cursor(state.simulation.cloth(), state.rig.camera(),
                                  w.framebuffer.width(), w.framebuffer.height(), cursor());
    if (!hit) return;  // only grabs when the cursor is on the cloth
    state.simulation.start_drag(grab_cloth(state.simulation.cloth(), *hit, state.drag_radius));
}

void move_drag(DemoState& state, const Window& w, const Hand& hand) {
    if (!state.simulation.drag().active()) return;
    if (auto target = point_on_grab_plane(state.rig.camera(), w.framebuffer.width(),
                                          w.framebuffer.height(), cursor(), hand.anchor))
        state.simulation.move_drag_target(*target);
}

void toggle_pin_under_cursor(DemoState& state, const Window& w) {
    auto hit = cloth_under_cursor(state.simulation.cloth(), state.rig.camera(),
                                  w.framebuffer.width(), w.framebuffer.height(), cursor());
    if (hit)
        state.simulation.set_pinned(hit->particle,
                                    !state.simulation.cloth().is_pinned(hit->particle));
}

void save_screenshot(DemoState& state, const Window& w) {
    const std::string path = next_screenshot_path(".");
    std::string error;
    if (raster::write_png(w.framebuffer, path, &error)) {
        std::printf("screenshot: %s\n", path.c_str());
        std::fflush(stdout);
        say(state, "saved " + path);
    } else {
        say(state, "screenshot failed: " + error);
    }
}

// Returns false when the user quits.
bool handle_event(const SDL_Event& event, DemoState& state, Window& w, Hand& hand) {
    ImGui_ImplSDL2_ProcessEvent(&event);
    const ImGuiIO& io = ImGui::GetIO();
    if (event.type == SDL_QUIT) return false;
    if (event.type == SDL_KEYDOWN && !io.WantCaptureKeyboard && !event.key.repeat) {
        switch (event.key.keysym.sym) {
            case SDLK_ESCAPE:
                return false;
            case SDLK_p:
                state.paused = !state.paused;
                break;
            case SDLK_n:
                state.single_step = true;
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
            case SDLK_h:
            case SDLK_F1:
                state.show_help = !state.show_help;
                break;
            case SDLK_HOME:
            case SDLK_c:
                state.rig = state.initial_rig;
                break;
            case SDLK_t:
                toggle_pin_under_cursor(state, w);
                break;
            case SDLK_u:
                state.simulation.release_all_pins();
                break;
            case SDLK_SPACE:
                start_drag(state, w);
                if (state.simulation.drag().active())
                    hand.dragging = true, hand.anchor = state.simulation.drag().target;
                break;
            default:
                break;
        }
    }
    if (event.type == SDL_KEYUP && event.key.keysym.sym == SDLK_SPACE && hand.dragging) {
        state.simulation.end_drag();
        hand.dragging = false;
    }
    if (event.type == SDL_MOUSEBUTTONDOWN && !io.WantCaptureMouse) {
        if (event.button.button == SDL_BUTTON_LEFT) {
            start_drag(state, w);
            if (state.simulation.drag().active())
                hand.dragging = true, hand.anchor = state.simulation.drag().target;
        } else if (event.button.button == SDL_BUTTON_RIGHT) {
            hand.cutting = true;
            hand.last_cursor = cursor();
        } else if (event.button.button == SDL_BUTTON_MIDDLE) {
            toggle_pin_under_cursor(state, w);
        }
    }
    if (event.type == SDL_MOUSEBUTTONUP) {
        if (event.button.button == SDL_BUTTON_LEFT && hand.dragging) {
            state.simulation.end_drag();
            hand.dragging = false;
        }
        if (event.button.button == SDL_BUTTON_RIGHT) hand.cutting = false;
    }
    if (event.type == SDL_MOUSEMOTION) {
        if (hand.dragging) move_drag(state, w, hand);
        if (hand.cutting) {
            const glm::vec2 now = cursor();
            cut_along_stroke(state.simulation, state.rig.camera(), w.framebuffer.width(),
                             w.framebuffer.height(), hand.last_cursor, now);
            hand.last_cursor = now;
        }
    }
    if (event.type == SDL_MOUSEWHEEL && !io.WantCaptureMouse)
        state.rig.zoom(static_cast<float>(event.wheel.y), 1.5f);
    return true;
}

// Held keys move and turn the camera at rates independent of the frame rate.
void move_camera(DemoState& state, double seconds) {
    if (ImGui::GetIO().WantCaptureKeyboard) return;
    const Uint8* keys = SDL_GetKeyboardState(nullptr);
    const glm::vec3 direction(float(keys[SDL_SCANCODE_D]) - float(keys[SDL_SCANCODE_A]),
                              float(keys[SDL_SCANCODE_E]) - float(keys[SDL_SCANCODE_Q]),
                              float(keys[SDL_SCANCODE_W]) - float(keys[SDL_SCANCODE_S]));
    state.rig.move(direction, 1.0f, static_cast<float>(seconds));  // 1 m/s
    const float yaw = float(keys[SDL_SCANCODE_LEFT]) - float(keys[SDL_SCANCODE_RIGHT]);
    const float pitch = float(keys[SDL_SCANCODE_UP]) - float(keys[SDL_SCANCODE_DOWN]);
    state.rig.turn(1.2f * yaw, 1.2f * pitch, static_cast<float>(seconds));  // rad/s
}

// ---- stepping with recovery ---------------------------------------------------------------

// Steps the planned number; on divergence rolls back to the last sound state, halves dt and
// says so, so the demo keeps running instead of freezing or showing noise.
void step_simulation(DemoState& state, int steps) {
    Simulation& sim = state.simulation;
    for (int s = 0; s < steps; ++s) {
        const StepReport report = sim.step();
        if (report.diverged()) {
            char text[512];
            const double new_dt = 0.5 * sim.dt();
            std::snprintf(
                text, sizeof text,
                "diverged at t=%.3f s: %s — rolled back to t=%.3f s, dt halved to %.3g ms",
                sim.time(), report.divergence->c_str(),
                state.last_good ? state.last_good->time() : 0.0, new_dt * 1e3);
            if (state.last_good) {
                sim = *state.last_good;
            } else {
                sim.reset();
            }
            sim.set_dt(new_dt);
            state.cloth_view = view::ClothView(sim.cloth());
            ++state.recoveries;
            say(state, text);
            return;
        }
        // Keep a sound state from about a quarter second back.
        if (sim.time() - state.last_good_time >= 0.25) {
            state.last_good = sim;
            state.last_good_time = sim.time();
        }
    }
}

// ---- drawing --------------------------------------------------------------------------------

bool present_frame(DemoState& state, Window& w) {
    int width = 0, height = 0;
    SDL_GetRendererOutputSize(w.renderer, &width, &height);
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
    view::render_frame(w.framebuffer, state.rig.camera(), state.simulation.cloth(),
                       state.cloth_view, state.frame_options, state.ground_height,
                       state.simulation.colliders(), &w.draw_pool);
    SDL_UpdateTexture(w.texture, nullptr, w.framebuffer.colours().data(), width * 4);
    SDL_RenderCopy(w.renderer, w.texture, nullptr, nullptr);
    return true;
}

}  // namespace

int run_demo_window(const CommandLine& command_line, const char* default_scene_path) {
    const std::string path = command_line.scene_path.value_or(default_scene_path);
    std::optional<Scene> scene = load_checked_scene(path, command_line.overrides);
    if (!scene) return exit_bad_input;
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        std::fprintf(stderr, "error: cannot open a window: %s\n", SDL_GetError());
        return exit_bad_input;
    }
    DemoState state(path, command_line.overrides, *scene);
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
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
    ImGui::StyleColorsDark();
    ImGui_ImplSDL2_InitForSDLRenderer(w.window);
    ImGui_ImplSDLRenderer_Init(w.renderer);

    Hand hand;
    const double started = now_seconds();
    long long frames = 0;
    double total_sim_seconds = 0.0, total_raster_seconds = 0.0;
    double last = now_seconds();
    double seconds_per_step = 0.0;
    bool running = true;
    while (running) {
        SDL_Event event;
        while (SDL_PollEvent(&event))
            if (!handle_event(event, state, w, hand)) running = false;
        const double now = now_seconds();
        const double elapsed = now - last;
        last = now;
        move_camera(state, elapsed);
        if (hand.dragging) move_drag(state, w, hand);  // the camera may move under a held drag

        // Step: as many fixed steps as keep simulated time with the clock, within budget.
        StepClock::Plan plan =
            state.clock.advance(elapsed, state.simulation.dt(), seconds_per_step);
        if (state.paused) {
            state.clock.reset();
            plan = {state.single_step ? 1 : 0, false};
            state.single_step = false;
        }
        const double sim_start = now_seconds();
        step_simulation(state, plan.steps);
        const double sim_seconds = now_seconds() - sim_start;
        if (plan.steps > 0) seconds_per_step = sim_seconds / plan.steps;
        DemoStatistics& stats = state.statistics;
        stats.steps = plan.steps;
        stats.behind = plan.behind;
        stats.sim_seconds = sim_seconds;
        stats.frame_seconds = elapsed;
        stats.energy.push_back(static_cast<float>(
            measure_energy(state.simulation.cloth(), state.simulation.force_field()).total()));
        if (stats.energy.size() > 300) stats.energy.erase(stats.energy.begin());

        ImGui_ImplSDLRenderer_NewFrame();
        ImGui_ImplSDL2_NewFrame();
        ImGui::NewFrame();
        draw_control_panel(state);
        draw_help_overlay(state.show_help);
        draw_status_overlay(state, now);
        ImGui::Render();

        SDL_SetRenderDrawColor(w.renderer, 28, 30, 36, 255);
        SDL_RenderClear(w.renderer);
        const double raster_start = now_seconds();
        present_frame(state, w);
        stats.raster_seconds = now_seconds() - raster_start;
        ImGui_ImplSDLRenderer_RenderDrawData(ImGui::GetDrawData());
        ++frames;
        total_sim_seconds += stats.sim_seconds;
        total_raster_seconds += stats.raster_seconds;
        if (w.save_window_next_frame) {
            save_window_screenshot(state, w);
            w.save_window_next_frame = false;
        }
        SDL_RenderPresent(w.renderer);
    }

    const double seconds = now_seconds() - started;
    if (frames > 0)
        std::printf(
            "%lld frames in %.1f s: %.1f fps, %.2f ms stepping and %.2f ms drawing per frame\n",
            frames, seconds, static_cast<double>(frames) / seconds,
            1e3 * total_sim_seconds / static_cast<double>(frames),
            1e3 * total_raster_seconds / static_cast<double>(frames));
    if (command_line.dump_path) {
        std::ofstream dump(*command_line.dump_path, std::ios::binary | std::ios::trunc);
        write_state_csv(state.simulation.cloth(), dump);
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
