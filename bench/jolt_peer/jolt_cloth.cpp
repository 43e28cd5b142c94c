// jolt_cloth: Jolt Physics' XPBD soft-body cloth on weft's cloth_128 / cloth_256 sheets, as an
// outside peer for timing. Built the way Jolt's Samples/Utils/SoftBodyCreator.cpp (CreateCloth)
// builds a cloth: a triangulated grid, SoftBodySharedSettings::CreateConstraints, Optimize.
//
//   jolt_cloth --size 128|256 --session calm|hard_hand [--frames F] [--compliance sample|zero|weft]
//              [--bend distance|dihedral|none] [--lra none|euclidean|geodesic] [--hold
//              vertex|patch] [--threads T]
//              [--iterations I] [--sessions DIR] [--sleep] [--dump FILE]
#include <Jolt/Jolt.h>

#include <Jolt/Core/Factory.h>
#include <Jolt/Core/JobSystemSingleThreaded.h>
#include <Jolt/Core/JobSystemThreadPool.h>
#include <Jolt/Core/TempAllocator.h>
#include <Jolt/Physics/Body/BodyCreationSettings.h>
#include <Jolt/Physics/Body/BodyLock.h>
#include <Jolt/Physics/Collision/BroadPhase/BroadPhaseLayerInterfaceTable.h>
#include <Jolt/Physics/Collision/BroadPhase/ObjectVsBroadPhaseLayerFilterTable.h>
#include <Jolt/Physics/Collision/ObjectLayerPairFilterTable.h>
#include <Jolt/Physics/PhysicsSystem.h>
#include <Jolt/Physics/SoftBody/SoftBodyCreationSettings.h>
#include <Jolt/Physics/SoftBody/SoftBodyMotionProperties.h>
#include <Jolt/Physics/SoftBody/SoftBodySharedSettings.h>
#include <Jolt/RegisterTypes.h>

#include <toml++/toml.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <thread>
#include <vector>

using namespace JPH;

namespace {

struct Event {
    std::string kind;  // grab, pull, release
    int particle = -1;
    double radius = 0.0;
    Vec3 point = Vec3::sZero();   // grab: weft's hit point
    Vec3 target = Vec3::sZero();  // pull
};

[[noreturn]] void die(const std::string& what) {
    std::fprintf(stderr, "jolt_cloth: %s\n", what.c_str());
    std::exit(2);
}

Vec3 to_vec3(const toml::node* node, const char* what) {
    const toml::array* a = node ? node->as_array() : nullptr;
    if (!a || a->size() != 3) die(std::string("bad ") + what);
    return Vec3(float(a->get(0)->value<double>().value()),
                float(a->get(1)->value<double>().value()),
                float(a->get(2)->value<double>().value()));
}

std::multimap<int, Event> read_events(const std::string& path, int& steps) {
    toml::table file;
    try {
        file = toml::parse_file(path);
    } catch (const toml::parse_error& e) {
        die(path + ": " + std::string(e.description()));
    }
    steps = file["steps"].value_or(180);
    std::multimap<int, Event> events;
    if (const toml::array* list = file["events"].as_array()) {
        for (const toml::node& n : *list) {
            const toml::table& t = *n.as_table();
            Event e;
            const int step = t["step"].value_or(-1);
            e.kind = t["kind"].value_or(std::string());
            if (e.kind == "grab") {
                e.particle = t["particle"].value_or(-1);
                e.radius = t["radius"].value_or(0.0);
                e.point = to_vec3(t.get("point"), "grab point");
            } else if (e.kind == "pull") {
                e.target = to_vec3(t.get("target"), "pull target");
            }
            events.emplace(step, e);
        }
    }
    return events;
}

namespace Layers {
constexpr ObjectLayer MOVING = 0;
constexpr uint NUM = 1;
}  // namespace Layers

}  // namespace

int main(int argc, char** argv) {
    int size = 128;
    std::string session = "calm", compliance_mode = "sample", bend_mode = "distance",
                hold = "vertex";
    std::string lra_mode = "none";
    std::string sessions_dir = "../../assets/sessions", dump_path;  // from bench/jolt_peer
    int frames = -1, threads = 1, iterations = -1;
    bool allow_sleep = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) die("missing value for " + a);
            return argv[++i];
        };
        if (a == "--size")
            size = std::atoi(next().c_str());
        else if (a == "--session")
            session = next();
        else if (a == "--frames")
            frames = std::atoi(next().c_str());
        else if (a == "--compliance")
            compliance_mode = next();
        else if (a == "--bend")
            bend_mode = next();
        else if (a == "--hold")
            hold = next();
        else if (a == "--lra")
            lra_mode = next();
        else if (a == "--threads")
            threads = std::atoi(next().c_str());
        else if (a == "--iterations")
            iterations = std::atoi(next().c_str());
        else if (a == "--sessions")
            sessions_dir = next();
        else if (a == "--sleep")
            allow_sleep = true;
        else if (a == "--dump")
            dump_path = next();
        else if (a == "--help" || a == "-h") {
            std::printf(
                "jolt_cloth --size 128|256 --session calm|hard_hand [--frames F] [--compliance "
                "sample|zero|weft]\n"
                "           [--bend distance|dihedral|none] [--lra none|euclidean|geodesic] "
                "[--hold vertex|patch] [--threads T] [--iterations I]\n"
                "           [--sessions DIR] [--sleep] [--dump FILE]\n");
            return 0;
        } else
            die("unknown option " + a);
    }
    if (size != 128 && size != 256) die("--size must be 128 or 256");
    if (session != "calm" && session != "hard_hand") die("--session must be calm or hard_hand");

    // weft's scenes (assets/scenes/cloth_<N>.toml): 1.15 m square, 0.2 kg/m², horizontal at y =
    // 0.6, row r at z = -0.3 + r s, column c at x = -0.575 + c s, particle r * N + c, row 0 pinned.
    double spacing = size == 128 ? 0.009055 : 0.0045098;
    double particle_mass = size == 128 ? 0.0000164 : 0.00000407;
    if (const char* scale = std::getenv("JOLT_CLOTH_MASS_SCALE"))
        particle_mass *= std::atof(scale);  // diagnostics only
    const Vec3 origin(-0.575f, 0.6f, -0.3f);
    const float dt = 1.0f / 60.0f;

    const std::string session_path =
        sessions_dir + "/cloth_" + std::to_string(size) + "_" + session + ".toml";
    int session_steps = 180;
    std::multimap<int, Event> events = read_events(session_path, session_steps);
    if (frames < 0) frames = session_steps;

    RegisterDefaultAllocator();
    Factory::sInstance = new Factory();
    RegisterTypes();

    // One object layer, one broad phase layer: there is nothing else in the world.
    BroadPhaseLayerInterfaceTable bp_layers(Layers::NUM, 1);
    bp_layers.MapObjectToBroadPhaseLayer(Layers::MOVING, BroadPhaseLayer(0));
    ObjectLayerPairFilterTable pair_filter(Layers::NUM);
    pair_filter.EnableCollision(Layers::MOVING, Layers::MOVING);
    ObjectVsBroadPhaseLayerFilterTable bp_filter(bp_layers, 1, pair_filter, Layers::NUM);

    PhysicsSystem physics;
    physics.Init(16, 0, 16, 16, bp_layers, bp_filter, pair_filter);
    physics.SetGravity(Vec3(0.0f, -9.81f, 0.0f));

    // The cloth, as SoftBodyCreator::CreateCloth lays it out (x fastest, faces split the same way).
    Ref<SoftBodySharedSettings> shared = new SoftBodySharedSettings;
    uint n = uint(size);
    if (const char* o = std::getenv("JOLT_CLOTH_N")) n = uint(std::atoi(o));  // diagnostics only
    if (const char* o = std::getenv("JOLT_CLOTH_SPACING"))
        spacing = std::atof(o);  // diagnostics only
    for (uint z = 0; z < n; ++z)
        for (uint x = 0; x < n; ++x) {
            SoftBodySharedSettings::Vertex v;
            Vec3 p = origin + Vec3(float(x * spacing), 0.0f, float(z * spacing));
            p.StoreFloat3(&v.mPosition);
            v.mInvMass = z == 0 ? 0.0f : float(1.0 / particle_mass);
            shared->mVertices.push_back(v);
        }
    auto index = [n](uint x, uint z) { return x + z * n; };
    for (uint z = 0; z + 1 < n; ++z)
        for (uint x = 0; x + 1 < n; ++x) {
            SoftBodySharedSettings::Face f;
            f.mVertex[0] = index(x, z);
            f.mVertex[1] = index(x, z + 1);
            f.mVertex[2] = index(x + 1, z + 1);
            shared->AddFace(f);
            f.mVertex[1] = index(x + 1, z + 1);
            f.mVertex[2] = index(x + 1, z);
            shared->AddFace(f);
        }
    SoftBodySharedSettings::VertexAttributes va;  // Jolt's CreateCloth default: {1e-5, 1e-5, 1e-5}
    va.mCompliance = va.mShearCompliance = va.mBendCompliance = 1.0e-5f;
    if (compliance_mode == "zero") {
        va.mCompliance = va.mShearCompliance = va.mBendCompliance = 0.0f;
    } else if (compliance_mode == "weft") {  // 1/k of weft's springs: 200, 100, 5 N/m
        va.mCompliance = 1.0f / 200.0f;
        va.mShearCompliance = 1.0f / 100.0f;
        va.mBendCompliance = 1.0f / 5.0f;
    } else if (compliance_mode != "sample")
        die("--compliance must be sample, zero or weft");
    if (lra_mode == "euclidean")
        va.mLRAType = SoftBodySharedSettings::ELRAType::EuclideanDistance;
    else if (lra_mode == "geodesic")
        va.mLRAType = SoftBodySharedSettings::ELRAType::GeodesicDistance;
    else if (lra_mode != "none")
        die("--lra must be none, euclidean or geodesic");
    SoftBodySharedSettings::EBendType bend = SoftBodySharedSettings::EBendType::Distance;
    if (bend_mode == "dihedral")
        bend = SoftBodySharedSettings::EBendType::Dihedral;
    else if (bend_mode == "none")
        bend = SoftBodySharedSettings::EBendType::None;
    else if (bend_mode != "distance")
        die("--bend must be distance, dihedral or none");
    shared->CreateConstraints(&va, 1, bend);
    if (!std::getenv("JOLT_CLOTH_NO_OPTIMIZE"))
        shared->Optimize();  // (skipping: reference diagnostics only)

    if (const char* ref = std::getenv("JOLT_CLOTH_REFERENCE")) {
        // Diagnostics only: Jolt's soft-body step re-done in double precision, same constraint
        // order (after Optimize), same substeps, damping and velocity update; calm session only.
        const int it = iterations > 0 ? iterations : 5;
        const bool use_float = std::string(ref) == "float";
        const bool structural_only = std::getenv("JOLT_CLOTH_STRUCT_ONLY") != nullptr;
        const size_t nv = shared->mVertices.size();
        std::vector<double> X(3 * nv), P(3 * nv), V(3 * nv, 0.0), W(nv);
        for (size_t i = 0; i < nv; ++i) {
            X[3 * i] = shared->mVertices[i].mPosition.x;
            X[3 * i + 1] = shared->mVertices[i].mPosition.y;
            X[3 * i + 2] = shared->mVertices[i].mPosition.z;
            W[i] = shared->mVertices[i].mInvMass;
        }
        const double h = double(dt) / it, damp = 1.0 - 0.1 * h;
        for (int frame = 0; frame < frames; ++frame) {
            for (int k = 0; k < it; ++k) {
                for (size_t i = 0; i < nv; ++i) {
                    if (W[i] > 0) {
                        V[3 * i + 1] += -9.81 * h;
                        for (int c = 0; c < 3; ++c) V[3 * i + c] *= damp;
                    }
                    for (int c = 0; c < 3; ++c) {
                        P[3 * i + c] = X[3 * i + c];
                        X[3 * i + c] += V[3 * i + c] * h;
                    }
                }
                for (const SoftBodySharedSettings::Edge& e : shared->mEdgeConstraints) {
                    if (structural_only && e.mRestLength > 1.01 * spacing) continue;
                    const uint a = e.mVertex[0], b = e.mVertex[1];
                    double d[3], len2 = 0;
                    for (int c = 0; c < 3; ++c) {
                        d[c] = X[3 * b + c] - X[3 * a + c];
                        len2 += d[c] * d[c];
                    }
                    const double len = std::sqrt(len2);
                    const double denom = len * (W[a] + W[b] + e.mCompliance / (h * h));
                    if (denom < 1e-12) continue;
                    const double f = (len - e.mRestLength) / denom;
                    for (int c = 0; c < 3; ++c) {
                        X[3 * a + c] += W[a] * f * d[c];
                        X[3 * b + c] -= W[b] * f * d[c];
                    }
                    if (use_float)
                        for (int c = 0; c < 3; ++c) {
                            X[3 * a + c] = float(X[3 * a + c]);
                            X[3 * b + c] = float(X[3 * b + c]);
                        }
                }
                for (size_t i = 0; i < nv; ++i)
                    if (W[i] > 0)
                        for (int c = 0; c < 3; ++c)
                            V[3 * i + c] = (X[3 * i + c] - P[3 * i + c]) / h;
            }
            double worst = 0;
            for (const SoftBodySharedSettings::Edge& e : shared->mEdgeConstraints) {
                if (structural_only && e.mRestLength > 1.01 * spacing) continue;
                double len2 = 0;
                for (int c = 0; c < 3; ++c) {
                    const double d = X[3 * e.mVertex[1] + c] - X[3 * e.mVertex[0] + c];
                    len2 += d * d;
                }
                worst = std::max(worst, std::sqrt(len2) / e.mRestLength);
            }
            std::printf("reference frame %d: max edge stretch %.4f\n", frame, worst);
        }
        return 0;
    }

    SoftBodyCreationSettings cs(shared, RVec3::sZero(), Quat::sIdentity(), Layers::MOVING);
    cs.mAllowSleeping = allow_sleep;  // weft never sleeps; a sleeping cloth would cost nothing
    if (iterations > 0) cs.mNumIterations = uint32(iterations);
    const uint32 used_iterations = cs.mNumIterations;
    BodyInterface& bi = physics.GetBodyInterface();
    const BodyID cloth_id = bi.CreateAndAddSoftBody(cs, EActivation::Activate);
    physics.OptimizeBroadPhase();

    TempAllocatorImpl temp(256 * 1024 * 1024);
    JobSystem* jobs = nullptr;
    JobSystemSingleThreaded single(cMaxPhysicsJobs);
    JobSystemThreadPool* pool = nullptr;
    if (threads <= 1)
        jobs = &single;
    else
        jobs = pool = new JobSystemThreadPool(cMaxPhysicsJobs, cMaxPhysicsBarriers, threads - 1);

    const BodyLockInterfaceNoLock& locks = physics.GetBodyLockInterfaceNoLock();
    auto with_cloth = [&](auto&& fn) {
        BodyLockWrite lock(locks, cloth_id);
        Body& body = lock.GetBody();
        fn(body, *static_cast<SoftBodyMotionProperties*>(body.GetMotionProperties()));
    };
    auto world_positions = [&]() {
        std::vector<Vec3> out;
        with_cloth([&](Body& body, SoftBodyMotionProperties& mp) {
            const RMat44 com = body.GetCenterOfMassTransform();
            out.reserve(mp.GetVertices().size());
            for (const SoftBodyVertex& v : mp.GetVertices()) out.push_back(Vec3(com * v.mPosition));
        });
        return out;
    };

    // The hand: held vertices (kinematic, inverse mass 0) with their offsets, followers (patch
    // mode).
    struct Held {
        uint index;
        Vec3 grabbed;
    };
    std::vector<Held> held;
    std::vector<std::pair<uint, float>> followers;
    Vec3 grab_point = Vec3::sZero(), hand = Vec3::sZero(), last_hand = Vec3::sZero();
    bool holding = false;
    double grab_gap = -1.0;
    int held_count = 0;

    std::vector<double> ms;
    ms.reserve(size_t(frames));
    for (int frame = 0; frame < frames; ++frame) {
        auto range = events.equal_range(frame);
        for (auto it = range.first; it != range.second; ++it) {
            const Event& e = it->second;
            if (e.kind == "grab") {
                const std::vector<Vec3> x = world_positions();
                if (e.particle < 0 || size_t(e.particle) >= x.size())
                    die("grab particle out of range");
                grab_point = e.point;
                hand = e.point;
                last_hand = e.point;
                grab_gap = (x[size_t(e.particle)] - e.point).Length();
                held.clear();
                followers.clear();
                if (hold ==
                    "patch") {  // weft's grab.cpp: weight (1-(d/r)^2)^2 >= 1/2 held, below follows
                    // Centred on Jolt's own grabbed vertex (Jolt's sheet hangs elsewhere than
                    // weft's).
                    const Vec3 centre = x[size_t(e.particle)];
                    for (uint p = 0; p < x.size(); ++p) {
                        if (p < n) continue;  // pinned row
                        const float d2 = (x[p] - centre).LengthSq();
                        float w = 0.0f;
                        if (d2 < e.radius * e.radius) {
                            const float f = 1.0f - d2 / float(e.radius * e.radius);
                            w = f * f;
                        }
                        if (int(p) == e.particle) w = 1.0f;
                        if (w <= 0.0f) continue;
                        if (w < 0.5f)
                            followers.emplace_back(p, w);
                        else
                            held.push_back({p, x[p]});
                    }
                } else if (hold == "vertex") {
                    held.push_back({uint(e.particle), x[size_t(e.particle)]});
                } else
                    die("--hold must be vertex or patch");
                with_cloth([&](Body&, SoftBodyMotionProperties& mp) {
                    for (const Held& h : held) mp.GetVertex(h.index).mInvMass = 0.0f;
                });
                holding = true;
                held_count = int(held.size());
            } else if (e.kind == "pull") {
                hand = e.target;
            } else if (e.kind == "release") {
                with_cloth([&](Body&, SoftBodyMotionProperties& mp) {
                    for (const Held& h : held)
                        mp.GetVertex(h.index).mInvMass = float(1.0 / particle_mass);
                });
                held.clear();
                followers.clear();
                holding = false;
            }
        }
        if (holding) {  // kinematic vertices: velocity that takes them to their goal in this frame
            with_cloth([&](Body& body, SoftBodyMotionProperties& mp) {
                const RMat44 com = body.GetCenterOfMassTransform();
                const Vec3 shift = hand - grab_point;
                const Vec3 hand_velocity = (hand - last_hand) / dt;
                last_hand = hand;
                for (const Held& h : held) {
                    SoftBodyVertex& v = mp.GetVertex(h.index);
                    const Vec3 now = Vec3(com * v.mPosition);
                    v.mVelocity = (h.grabbed + shift - now) / dt;
                }
                for (const auto& [p, w] : followers) {
                    SoftBodyVertex& v = mp.GetVertex(p);
                    v.mVelocity += w * (hand_velocity - v.mVelocity);
                }
            });
        }
        const auto t0 = std::chrono::steady_clock::now();
        physics.Update(dt, 1, &temp, jobs);
        const auto t1 = std::chrono::steady_clock::now();
        ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
        if (std::getenv("JOLT_CLOTH_TRACE")) {  // diagnostics only: outside the timed region
            const std::vector<Vec3> xt = world_positions();
            double worst = 0.0, vmax = 0.0;
            uint wi = 0;
            for (uint z = 0; z + 1 < n; ++z)
                for (uint xx = 0; xx < n; ++xx) {
                    const double s1 = (xt[index(xx, z + 1)] - xt[index(xx, z)]).Length() / spacing;
                    if (s1 > worst) {
                        worst = s1;
                        wi = index(xx, z);
                    }
                    if (xx + 1 < n) {
                        const double s2 =
                            (xt[index(xx + 1, z)] - xt[index(xx, z)]).Length() / spacing;
                        if (s2 > worst) {
                            worst = s2;
                            wi = index(xx, z);
                        }
                    }
                }
            with_cloth([&](Body&, SoftBodyMotionProperties& mp) {
                for (const SoftBodyVertex& v : mp.GetVertices())
                    vmax = std::max(vmax, double(v.mVelocity.Length()));
            });
            std::printf(
                "frame %d: max stretch %.4f at row %u col %u, max speed %.3f m/s, tip y %.4f z "
                "%.4f\n",
                frame, worst, wi / n, wi % n, vmax, xt[index(n / 2, n - 1)].GetY(),
                xt[index(n / 2, n - 1)].GetZ());
        }
    }

    // Quality: the largest stretch (length / rest) of the grid's structural edges, and of all
    // of Jolt's edge constraints (structural, shear, distance-bend).
    const std::vector<Vec3> x = world_positions();
    double worst_structural = 0.0, worst_edge = 0.0, sum_structural = 0.0;
    size_t structural_count = 0;
    bool finite = true;
    for (const Vec3& p : x)
        finite =
            finite && std::isfinite(p.GetX()) && std::isfinite(p.GetY()) && std::isfinite(p.GetZ());
    for (uint z = 0; z < n; ++z)
        for (uint xx = 0; xx < n; ++xx) {
            const Vec3 p = x[index(xx, z)];
            if (xx + 1 < n) {
                const double s = (x[index(xx + 1, z)] - p).Length() / spacing;
                worst_structural = std::max(worst_structural, s);
                sum_structural += s;
                ++structural_count;
            }
            if (z + 1 < n) {
                const double s = (x[index(xx, z + 1)] - p).Length() / spacing;
                worst_structural = std::max(worst_structural, s);
                sum_structural += s;
                ++structural_count;
            }
        }
    uint worst_a = 0, worst_b = 0;
    for (const SoftBodySharedSettings::Edge& e : shared->mEdgeConstraints) {
        const double s = double((x[e.mVertex[1]] - x[e.mVertex[0]]).Length() / e.mRestLength);
        if (s > worst_edge) {
            worst_edge = s;
            worst_a = e.mVertex[0];
            worst_b = e.mVertex[1];
        }
    }
    if (std::getenv("JOLT_CLOTH_DEBUG"))
        std::printf("worst edge %u (row %u col %u) - %u (row %u col %u)\n", worst_a, worst_a / n,
                    worst_a % n, worst_b, worst_b / n, worst_b % n);
    double hand_error = 0.0;
    for (const Held& h : held)
        hand_error =
            std::max(hand_error, double((x[h.index] - (h.grabbed + hand - grab_point)).Length()));

    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    const size_t m = sorted.size();
    const double median =
        m == 0 ? 0.0 : (m % 2 ? sorted[m / 2] : 0.5 * (sorted[m / 2 - 1] + sorted[m / 2]));
    double total = 0.0;
    for (double t : ms) total += t;
    const double mean = m ? total / double(m) : 0.0;

    std::printf(
        "jolt_cloth size=%d session=%s frames=%d threads=%d iterations=%u compliance=%s(edge %g "
        "shear %g bend %g) bend=%s lra=%s hold=%s sleep=%s\n",
        size, session.c_str(), frames, threads, used_iterations, compliance_mode.c_str(),
        va.mCompliance, va.mShearCompliance, va.mBendCompliance, bend_mode.c_str(),
        lra_mode.c_str(), hold.c_str(), allow_sleep ? "on" : "off");
    std::printf("constraints: %zu edge (incl. shear%s), %zu dihedral, %zu LRA; vertices %zu\n",
                shared->mEdgeConstraints.size(),
                bend == SoftBodySharedSettings::EBendType::Distance ? " and distance-bend" : "",
                shared->mDihedralBendConstraints.size(), shared->mLRAConstraints.size(),
                shared->mVertices.size());
    if (grab_gap >= 0.0)
        std::printf(
            "hand: %d held, %zu followers; Jolt's grabbed vertex was %.4f m from weft's grab "
            "point; held vertex off its goal by %.2e m at the end\n",
            held_count, followers.size(), grab_gap, hand_error);
    std::printf("ms/frame: median %.4f mean %.4f min %.4f max %.4f (total %.1f ms)\n", median, mean,
                sorted.front(), sorted.back(), total);
    std::printf(
        "end stretch: structural max %.4f mean %.5f; all edge constraints max %.4f; finite=%s\n",
        worst_structural, sum_structural / double(structural_count), worst_edge,
        finite ? "yes" : "NO");
    std::printf("RESULT median_ms=%.4f mean_ms=%.4f max_structural_stretch=%.4f\n", median, mean,
                worst_structural);

    if (!dump_path.empty()) {
        FILE* f = std::fopen(dump_path.c_str(), "w");
        if (!f) die("cannot write " + dump_path);
        std::fprintf(f, "row,col,x,y,z\n");
        for (uint z = 0; z < n; ++z)
            for (uint xx = 0; xx < n; ++xx) {
                const Vec3 p = x[index(xx, z)];
                std::fprintf(f, "%u,%u,%.9g,%.9g,%.9g\n", z, xx, p.GetX(), p.GetY(), p.GetZ());
            }
        std::fclose(f);
    }

    bi.RemoveBody(cloth_id);
    bi.DestroyBody(cloth_id);
    delete pool;
    UnregisterTypes();
    delete Factory::sInstance;
    Factory::sInstance = nullptr;
    return finite ? 0 : 3;
}
