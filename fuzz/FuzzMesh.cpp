// libFuzzer target: bytes from the fuzzer as a mesh file, as a stranger's design or session can
// name one (marbler/gl/Meshes.h). The first byte chooses the file's name (.obj, .stl, .ply,
// .gltf, .glb, .dae), the rest is its content, written to a file as the loader reads files. The
// checks (MeshFileCheck.h) and assimp's four importers must load it or refuse it with a one-line
// InputError. Anything else (a crash, a sanitizer report, a hang, another exception) is a
// finding. assimp is Debian's, not instrumented: the fuzzer sees coverage of Marbler's checks
// only, while AddressSanitizer still catches what assimp does to memory.

#include "marbler/Error.h"
#include "marbler/gl/Meshes.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

[[noreturn]] void finding(const char* what, const std::string& detail = {}) {
    std::fprintf(stderr, "fuzz_mesh: %s\n%s\n", what, detail.c_str());
    std::abort();
}

/// A folder of this process's own, so parallel fuzzing jobs do not share files.
const std::filesystem::path& folder() {
    static const std::filesystem::path dir = [] {
        auto d = std::filesystem::temp_directory_path() / ("marbler-fuzz-mesh-" + std::to_string(getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    return dir;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    static const char* names[] = {"m.obj", "m.stl", "m.ply", "m.gltf", "m.glb", "m.dae"};
    const std::filesystem::path file = folder() / names[data[0] % 6];
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
    }
    try {
        marbler::MeshData mesh = marbler::gl::loadMesh(file.string());
        for (std::uint32_t i : mesh.indices)
            if (i >= mesh.positions.size()) finding("an index past the vertices");
    } catch (const marbler::InputError& e) {
        if (std::string(e.what()).find('\n') != std::string::npos)
            finding("multi-line error message", e.what());
    }
    std::filesystem::remove(file);
    return 0;
}
