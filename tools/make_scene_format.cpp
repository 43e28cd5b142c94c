// weft-make-scene-format: writes docs/scene-format.md, the reference of every scene key, from
// the key table (src/sim/scene/scene_keys.cpp), so the reference cannot drift from what the loader,
// --set and the panel accept. The test tools.scene_format runs it with --check.
//
//   weft-make-scene-format FILE           write the reference to FILE
//   weft-make-scene-format --check FILE   exit 1 if FILE is not what this writes
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "sim/scene/scene_keys.h"

int main(int argc, char** argv) {
    const char* usage =
        "usage: weft-make-scene-format [--check] FILE\n"
        "       weft-make-scene-format --help | --version\n"
        "\n"
        "Writes the scene format's reference (docs/scene-format.md) to FILE, from the scene key\n"
        "table; --check only compares it with FILE (status 1 if they differ).\n";
    // Every program answers --help and --version, this one too.
    const std::string first = argc == 2 ? argv[1] : "";
    if (first == "--help" || first == "-h") {
        std::cout << usage;
        return 0;
    }
    if (first == "--version") {
        std::cout << "weft-make-scene-format " << WEFT_VERSION << "\n";
        return 0;
    }
    const bool check = argc == 3 && std::string(argv[1]) == "--check";
    if (!(argc == 2 && argv[1][0] != '-') && !check) {
        std::cerr << usage;
        return 2;
    }
    const std::string path = argv[argc - 1];
    const std::string text = weft::scene_format_markdown();
    if (check) {
        std::ifstream file(path, std::ios::binary);
        std::ostringstream on_disk;
        on_disk << file.rdbuf();
        if (!file || on_disk.str() != text) {
            std::cerr << "weft-make-scene-format: " << path
                      << " is not what the scene key table gives; run weft-make-scene-format "
                      << path << "\n";
            return 1;
        }
        return 0;
    }
    std::ofstream file(path, std::ios::binary);
    file << text;
    if (!file) {
        std::cerr << "weft-make-scene-format: cannot write " << path << "\n";
        return 2;
    }
    return 0;
}
