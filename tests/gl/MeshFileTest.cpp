// A mesh file may come from a stranger with a design or a session (Meshes.h): only OBJ, STL,
// PLY and glTF/GLB are read, and what a header announces is checked before anything is
// allocated for it. Before the checks, a PLY header announcing 4·10⁹ vertices ended in
// "cannot load mesh: std::bad_alloc" (or the process was killed), and any of assimp's forty-odd
// importers would read a file named as a mesh.

#include "TestUtil.h"
#include "marbler/Error.h"
#include "marbler/gl/Meshes.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>

namespace marbler {
namespace {

namespace fs = std::filesystem;

/// A folder of the test's own.
fs::path folder() {
    const fs::path dir = test::outputDir(std::string("mesh-files-") +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

/// The message loading `file` gives ("" when it loads).
std::string errorOf(const fs::path& file) {
    try {
        gl::loadMesh(file.string());
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

std::string le32(std::uint32_t v) {
    std::string s(4, '\0');
    for (int i = 0; i < 4; ++i)
        s[std::size_t(i)] = char((v >> (8 * i)) & 0xff);
    return s;
}

std::string f32(float v) {
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    return le32(bits);
}

/// A binary STL of one triangle, its header's count `announced`.
std::string binaryStl(std::uint32_t announced) {
    std::string stl(80, ' ');
    stl += le32(announced);
    for (float v : {0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f})
        stl += f32(v);
    stl += std::string(2, '\0');
    return stl;
}

const char* Tetra = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

/// A glTF of one triangle whose buffer is `uri` (byteLength 42: three float positions and three
/// 16-bit indices), with `count` positions announced.
std::string gltf(const std::string& uri, std::uint64_t count = 3) {
    return R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
 "buffers": [{"byteLength": 42, "uri": ")" +
           uri + R"("}],
 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" +
           std::to_string(count) + R"(, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
               {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})";
}

std::string triangleBuffer() {
    std::string b;
    for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f})
        b += f32(v);
    b += std::string("\0\0\1\0\2\0", 6);
    return b;
}

TEST(MeshFiles, EveryAllowedFormatStillLoads) {
    const fs::path dir = folder();
    test::writeFile(dir / "tetra.obj", Tetra);
    test::writeFile(dir / "tetra.ply",
                    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
                    "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    test::writeFile(dir / "one.stl", binaryStl(1));
    test::writeFile(dir / "one.bin", triangleBuffer());
    test::writeFile(dir / "one.gltf", gltf("one.bin"));
    for (const char* name : {"tetra.obj", "tetra.ply", "one.stl", "one.gltf"}) {
        const std::string error = errorOf(dir / name);
        EXPECT_EQ(error, "") << name;
    }
    EXPECT_EQ(gl::loadMesh((dir / "tetra.ply").string()).indices.size(), 12u);
    EXPECT_EQ(gl::loadMesh((dir / "one.gltf").string()).indices.size(), 3u);
}

TEST(MeshFiles, AnnouncedCountsAreCheckedBeforeReading) {
    const fs::path dir = folder();
    test::writeFile(dir / "huge.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
                                      "property float x\nproperty float y\nproperty float z\nend_header\n" +
                                          std::string(12, '\0'));
    std::string error = errorOf(dir / "huge.ply");
    EXPECT_NE(error.find("huge.ply: cannot load mesh: the file announces 4,000,000,000 vertices (at most "
                         "16,000,000 are read)"),
              std::string::npos)
        << error;

    test::writeFile(dir / "short.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 1000\n"
                                       "property float x\nproperty float y\nproperty float z\nend_header\n" +
                                           std::string(24, '\0'));
    error = errorOf(dir / "short.ply");
    EXPECT_NE(error.find("announces more than the file holds"), std::string::npos) << error;

    test::writeFile(dir / "lying.stl", binaryStl(500000000));
    error = errorOf(dir / "lying.stl");
    EXPECT_NE(error.find("a damaged binary STL file: its header says 500,000,000 triangles"),
              std::string::npos)
        << error;

    test::writeFile(dir / "one.bin", triangleBuffer());
    test::writeFile(dir / "many.gltf", gltf("one.bin", 1000000000000ull));
    error = errorOf(dir / "many.gltf");
    EXPECT_NE(error.find("announces 1,000,000,000,000 elements in an accessor"), std::string::npos) << error;
    test::writeFile(dir / "past.gltf", gltf("one.bin", 40));
    error = errorOf(dir / "past.gltf");
    EXPECT_NE(error.find("a glTF accessor of 40 elements in a bufferView of 36 bytes"), std::string::npos)
        << error;
}

TEST(MeshFiles, AFaceOfVerticesThatDoNotExistIsRefusedNotAborted) {
    // Found by fuzz_mesh: assimp's triangulation asserts (and aborts) on an index past the
    // vertices, which its validation step refuses first.
    const fs::path dir = folder();
    test::writeFile(dir / "dangling.ply", "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                                          "property float y\nproperty float z\nelement face 1\n"
                                          "property list uchar int vertex_indices\nend_header\n"
                                          "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    const std::string error = errorOf(dir / "dangling.ply");
    EXPECT_NE(error.find("dangling.ply: cannot load mesh: "), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST(MeshFiles, APlyHeaderIsReadWholeBeforeAssimpSeesIt) {
    // Found by fuzz_mesh (valgrind: "Invalid write of size 4" in Debian's assimp 5.2.4, past a
    // 24-byte block): a property line with words left over and a second header after the first
    // made assimp's PLY reader write past its buffers. Every line the format does not define is
    // refused with the line.
    const fs::path dir = folder();
    const std::string body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    test::writeFile(dir / "found.ply",
                    "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float yoperty "
                    "floatoat z\nelement face 1\nproperty list uchar int vertex_indices\nend_h ascii 1.0\n"
                    "end_header\n" +
                        body);
    std::string error = errorOf(dir / "found.ply");
    EXPECT_EQ(error, (dir / "found.ply").string() +
                         ": cannot load mesh: a PLY header with a bad property line: 'property float yoperty "
                         "floatoat z'");
    struct Case {
        std::string header, why;
    };
    const std::string vertex = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
    const std::string face = "element face 1\nproperty list uchar int vertex_indices\n";
    for (const Case& c : {
             Case{"format ascii 1.0\n" + vertex + "format ascii 1.0\n" + face, "with a second format line"},
             Case{"format ebcdic 1.0\n" + vertex + face, "that does not begin with a known format"},
             Case{vertex + face, "that does not begin with a known format"},
             Case{"comment first\nformat ascii 1.0\n" + vertex + face,
                  "that does not begin with a known format"},
             Case{"format ascii 1.0\nproperty float x\n" + vertex + face,
                  "with a property before any element"},
             Case{"format ascii 1.0\n" + vertex + "property float x\n" + face, "naming a property twice"},
             Case{"format ascii 1.0\n" + vertex + face + "element vertex 1\n", "naming an element twice"},
             Case{"format ascii 1.0\n" + vertex + "element face 1\nproperty list float int i\n",
                  "with a bad property line"},
             Case{"format ascii 1.0\n" + vertex + "element face 1 2\n", "with a bad element line"},
             Case{"format ascii 1.0\n" + vertex + face + "end_h ascii 1.0\n",
                  "with a line the format does not define"},
         }) {
        test::writeFile(dir / "bad.ply", "ply\n" + c.header + "end_header\n" + body);
        error = errorOf(dir / "bad.ply");
        EXPECT_NE(error.find("cannot load mesh: a PLY header " + c.why + ": '"), std::string::npos)
            << c.header << "\n"
            << error;
    }
    // Comments and obj_info lines are the format's own, anywhere after the format line.
    test::writeFile(dir / "commented.ply", "ply\nformat ascii 1.0\ncomment made by hand\nobj_info a tetra\n" +
                                               vertex + "comment faces next\n" + face + "end_header\n" +
                                               body);
    EXPECT_EQ(errorOf(dir / "commented.ply"), "");
}

TEST(MeshFiles, OtherKindsAreRefusedByWhatTheyAre) {
    const fs::path dir = folder();
    const std::string collada = "<?xml version=\"1.0\"?>\n<COLLADA xmlns=\"http://www.collada.org/2005/11/"
                                "COLLADASchema\" version=\"1.4.1\"></COLLADA>\n";
    test::writeFile(dir / "disguised.obj", collada);
    test::writeFile(dir / "model.dae", collada);
    test::writeFile(dir / "model.fbx", std::string("Kaydara FBX Binary  \0\x1a\0", 23));
    test::writeFile(dir / "model.3ds", std::string("\x4d\x4d\x10\0\0\0", 6));
    test::writeFile(dir / "model.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    struct Case {
        const char* name;
        const char* says;
    };
    for (const Case& c : {Case{"disguised.obj", "a Collada file: meshes must be OBJ, STL, PLY or glTF"},
                          Case{"model.dae", "a Collada file: meshes must be"},
                          Case{"model.fbx", "an FBX file: meshes must be"}, Case{"model.3ds", "a 3DS file"},
                          Case{"model.off", "a file of a kind Marbler does not read"}}) {
        const std::string error = errorOf(dir / c.name);
        EXPECT_NE(error.find((dir / c.name).string() + ": cannot load mesh: "), std::string::npos) << error;
        EXPECT_NE(error.find(c.says), std::string::npos) << c.name << ": " << error;
    }
}

TEST(MeshFiles, AGltfReadsNoBufferOutsideItsFolder) {
    const fs::path dir = folder();
    fs::create_directories(dir / "design");
    test::writeFile(dir / "secret.bin", triangleBuffer());
    test::writeFile(dir / "design" / "leak.gltf", gltf("../secret.bin"));
    std::string error = errorOf(dir / "design" / "leak.gltf");
    EXPECT_NE(error.find("a glTF buffer '../secret.bin' outside the mesh's folder"), std::string::npos)
        << error;
    test::writeFile(dir / "design" / "absolute.gltf", gltf((dir / "secret.bin").string()));
    error = errorOf(dir / "design" / "absolute.gltf");
    EXPECT_NE(error.find("outside the mesh's folder"), std::string::npos) << error;
}

} // namespace
} // namespace marbler
