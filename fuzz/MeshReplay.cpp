// Every file of a fuzz_mesh corpus through the mesh loader, in one process, for valgrind
// (fuzz/mesh-valgrind.sh): assimp is Debian's and not instrumented, so a write past one of its
// own buffers is invisible to AddressSanitizer until it breaks a chunk's header later, under
// another input. The first byte of an input chooses the file's name, as in FuzzMesh.cpp.

#include "marbler/Error.h"
#include "marbler/Mesh.h"
#include "marbler/gl/Meshes.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace marbler {
// The built-in objects are not read from files; the loader's fallback for their names is not
// what is checked here.
std::vector<std::string> builtinMeshNames() {
    return {};
}
MeshData builtinMesh(const std::string&) {
    return {};
}
} // namespace marbler

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: mesh_replay CORPUS-FOLDER SCRATCH-FOLDER\n");
        return 2;
    }
    static const char* names[] = {"m.obj", "m.stl", "m.ply", "m.gltf", "m.glb", "m.dae"};
    std::filesystem::create_directories(argv[2]);
    int inputs = 0;
    for (const auto& entry : std::filesystem::directory_iterator(argv[1])) {
        std::ifstream in(entry.path(), std::ios::binary);
        const std::string data((std::istreambuf_iterator<char>(in)), {});
        if (data.empty()) continue;
        const auto file = std::filesystem::path(argv[2]) / names[static_cast<unsigned char>(data[0]) % 6];
        {
            std::ofstream out(file, std::ios::binary | std::ios::trunc);
            out.write(data.data() + 1, std::streamsize(data.size() - 1));
        }
        std::fprintf(stderr, "== %s\n", entry.path().filename().c_str());
        try {
            marbler::gl::loadMesh(file.string());
        } catch (const marbler::Error&) {
        }
        ++inputs;
    }
    std::fprintf(stderr, "mesh_replay: %d inputs read\n", inputs);
    return 0;
}
