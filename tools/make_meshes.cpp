// weft-make-meshes: writes the shipped cloth meshes (assets/meshes/*.obj), so that they are
// made in the repository, not downloaded, and can be made again at another resolution.
//
//   weft-make-meshes DIRECTORY           write the meshes into DIRECTORY
//   weft-make-meshes --check DIRECTORY   exit 1 if a mesh there is not what this writes
//
// Each mesh is laid out at rest, in metres, with edges of about 4 cm (the shipped tablecloth
// scene's spacing), and names the vertices its scene pins as an OBJ group (`g`, then `p`).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct ObjWriter {
    std::ostringstream text;
    int vertices = 0;

    explicit ObjWriter(const std::string& comment) {
        text << "# " << comment << "\n# Written by tools/make_meshes.cpp; do not edit.\n";
    }
    int vertex(double x, double y, double z) {  // m; returns its 1-based number
        char line[96];
        std::snprintf(line, sizeof line, "v %.6f %.6f %.6f\n", x, y, z);
        text << line;
        return ++vertices;
    }
    void triangle(int a, int b, int c) { text << "f " << a << ' ' << b << ' ' << c << '\n'; }
    void quad(int a, int b, int c, int d) {
        text << "f " << a << ' ' << b << ' ' << c << ' ' << d << '\n';
    }
    void group(const std::string& name, const std::vector<int>& members) {
        text << "g " << name << "\np";
        for (int v : members) text << ' ' << v;
        text << '\n';
    }
};

// A round tablecloth, 0.8 m in radius, lying flat (y = 0) around the origin: a centre vertex
// and 20 rings, ring k holding 6k vertices, each ring joined to the one inside it by
// triangles (the hexagonal disc: edges of 3.8-4.4 cm, no sliver anywhere).
std::string round_tablecloth() {
    ObjWriter obj("A round tablecloth, 0.8 m in radius, flat, in triangles");
    constexpr int rings = 20;
    constexpr double radius = 0.8;  // m
    std::vector<std::vector<int>> ring(rings + 1);
    ring[0].push_back(obj.vertex(0.0, 0.0, 0.0));
    for (int k = 1; k <= rings; ++k) {
        const double r = radius * k / rings;
        for (int i = 0; i < 6 * k; ++i) {
            // Along a hexagon's side, then pushed out onto the circle: corner c of the hexagon,
            // step i % k of k along its side.
            const int side = i / k, step = i % k;
            const double a0 = std::numbers::pi / 3.0 * side,
                         a1 = std::numbers::pi / 3.0 * (side + 1);
            const double t = static_cast<double>(step) / k;
            const double hx = (1 - t) * std::cos(a0) + t * std::cos(a1);
            const double hz = (1 - t) * std::sin(a0) + t * std::sin(a1);
            const double angle = std::atan2(hz, hx);
            ring[k].push_back(obj.vertex(r * std::cos(angle), 0.0, r * std::sin(angle)));
        }
    }
    // Between ring k - 1 (6(k - 1) vertices) and ring k (6k): per side of the hexagon, k outer
    // and k - 1 inner vertices make 2k - 1 triangles, wound counter-clockwise seen from +y.
    for (int k = 1; k <= rings; ++k) {
        const std::vector<int>& inner = ring[k - 1];
        const std::vector<int>& outer = ring[k];
        const int n_inner = static_cast<int>(inner.size()),
                  n_outer = static_cast<int>(outer.size());
        for (int side = 0; side < 6; ++side) {
            for (int step = 0; step < k; ++step) {
                const int o0 = side * k + step, o1 = (o0 + 1) % n_outer;
                const int i0 = k == 1 ? 0 : (side * (k - 1) + step) % n_inner;
                obj.triangle(outer[o0], inner[i0], outer[o1]);
                if (step < k - 1) {
                    const int i1 = (side * (k - 1) + step + 1) % n_inner;
                    obj.triangle(inner[i0], inner[i1], outer[o1]);
                }
            }
        }
    }
    return obj.text.str();
}

// A flag 1.2 m by 0.8 m in the x-y plane, its pole along x = 0, in quads of 4 cm, with a round
// hole 0.14 m in radius in its middle (the quads whose centre falls inside are left out, and
// so are vertices no quad uses). Group "pole": the vertices on the pole.
std::string flag_with_hole() {
    ObjWriter obj("A flag 1.2 m by 0.8 m with a round hole, in quads; group pole: its pole edge");
    constexpr int cols = 30, rows = 20;                               // quads
    constexpr double cell = 0.04;                                     // m
    constexpr double hole_x = 0.6, hole_y = 0.4, hole_radius = 0.14;  // m
    auto in_hole = [&](int c, int r) {
        const double x = (c + 0.5) * cell - hole_x, y = (r + 0.5) * cell - hole_y;
        return x * x + y * y < hole_radius * hole_radius;
    };
    std::vector<int> number((cols + 1) * (rows + 1), 0);
    auto used = [&](int c, int r) {  // a vertex of some kept quad
        for (int dc = -1; dc <= 0; ++dc)
            for (int dr = -1; dr <= 0; ++dr) {
                const int qc = c + dc, qr = r + dr;
                if (qc >= 0 && qc < cols && qr >= 0 && qr < rows && !in_hole(qc, qr)) return true;
            }
        return false;
    };
    std::vector<int> pole;
    for (int r = 0; r <= rows; ++r)
        for (int c = 0; c <= cols; ++c)
            if (used(c, r)) {
                number[r * (cols + 1) + c] = obj.vertex(c * cell, r * cell, 0.0);
                if (c == 0) pole.push_back(number[r * (cols + 1) + c]);
            }
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c)
            if (!in_hole(c, r)) {
                auto at = [&](int cc, int rr) { return number[rr * (cols + 1) + cc]; };
                obj.quad(at(c, r), at(c + 1, r), at(c + 1, r + 1), at(c, r + 1));  // front: +z
            }
    obj.group("pole", pole);
    return obj.text.str();
}

// A skirt: the side of a cone cut across, 0.16 m in radius at the waist (y = 1) and 0.42 m at
// the hem (y = 0.45), around the y axis, in quads (40 around, 14 down) closed at the seam.
// Group "waist": the top ring.
std::string skirt() {
    ObjWriter obj("A skirt, a cut cone 0.55 m long, in quads; group waist: its top ring");
    constexpr int around = 40, down = 14;
    constexpr double waist = 0.16, hem = 0.42, top = 1.0, length = 0.55;  // m
    std::vector<int> waist_ring;
    for (int r = 0; r <= down; ++r) {
        const double t = static_cast<double>(r) / down;
        const double radius = waist + (hem - waist) * t, y = top - length * t;
        for (int a = 0; a < around; ++a) {
            const double angle = 2.0 * std::numbers::pi * a / around;
            const int v = obj.vertex(radius * std::cos(angle), y, radius * std::sin(angle));
            if (r == 0) waist_ring.push_back(v);
        }
    }
    for (int r = 0; r < down; ++r)
        for (int a = 0; a < around; ++a) {
            const int b = (a + 1) % around;
            auto at = [&](int rr, int aa) { return 1 + rr * around + aa; };
            obj.quad(at(r, a), at(r, b), at(r + 1, b), at(r + 1, a));  // front: outward
        }
    obj.group("waist", waist_ring);
    return obj.text.str();
}

struct Mesh {
    const char* file;
    std::string (*make)();
};
constexpr Mesh meshes[] = {{"round_tablecloth.obj", round_tablecloth},
                           {"flag_with_hole.obj", flag_with_hole},
                           {"skirt.obj", skirt}};

}  // namespace

int main(int argc, char** argv) {
    const char* usage =
        "usage: weft-make-meshes [--check] DIRECTORY\n"
        "       weft-make-meshes --help | --version\n"
        "\n"
        "Writes the shipped meshes (skirt.obj, flag_with_hole.obj, round_tablecloth.obj) into\n"
        "DIRECTORY; --check only compares them with the files there (status 1 if they differ).\n";
    // Every program answers --help and --version, this one too.
    const std::string first = argc == 2 ? argv[1] : "";
    if (first == "--help" || first == "-h") {
        std::cout << usage;
        return 0;
    }
    if (first == "--version") {
        std::cout << "weft-make-meshes " << WEFT_VERSION << "\n";
        return 0;
    }
    const bool check = argc == 3 && std::string(argv[1]) == "--check";
    if (!(argc == 2 && argv[1][0] != '-') && !check) {
        std::cerr << usage;
        return 2;
    }
    const std::string directory = argv[argc - 1];
    int status = 0;
    for (const Mesh& mesh : meshes) {
        const std::string path = directory + "/" + mesh.file;
        const std::string text = mesh.make();
        if (check) {
            std::ifstream file(path, std::ios::binary);
            std::ostringstream on_disk;
            on_disk << file.rdbuf();
            if (!file || on_disk.str() != text) {
                std::cerr << "weft-make-meshes: " << path
                          << " is not what tools/make_meshes.cpp writes; run it again\n";
                status = 1;
            }
        } else {
            std::ofstream file(path, std::ios::binary);
            file << text;
            if (!file) {
                std::cerr << "weft-make-meshes: cannot write " << path << "\n";
                return 2;
            }
        }
    }
    return status;
}
