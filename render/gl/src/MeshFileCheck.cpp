#include "MeshFileCheck.h"

#include "marbler/Error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace marbler::gl::detail {
namespace {

namespace fs = std::filesystem;

std::string count(std::uint64_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

[[noreturn]] void refuse(const std::string& what) {
    throw InputError(what);
}

void checkCap(std::uint64_t n, std::uint64_t cap, const std::string& what) {
    if (n > cap)
        refuse("the file announces " + count(n) + " " + what + " (at most " + count(cap) + " are read)");
}

std::string lowerExtension(const std::string& file) {
    std::string ext = fs::path(file).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

bool startsWith(const std::string& head, std::string_view magic) {
    return head.rfind(magic, 0) == 0;
}

/// What a file of another kind is, for the refusal; empty when unknown.
std::string otherKind(const std::string& head) {
    if (head.find("COLLADA") != std::string::npos) return "a Collada file";
    if (startsWith(head, "Kaydara FBX Binary") || head.find("FBXHeaderExtension") != std::string::npos)
        return "an FBX file";
    if (startsWith(head, "BLENDER")) return "a Blender file";
    if (head.size() >= 2 && std::uint8_t(head[0]) == 0x4d && std::uint8_t(head[1]) == 0x4d)
        return "a 3DS file";
    if (startsWith(head, "PK\x03\x04")) return "a ZIP archive (such as 3MF)";
    if (startsWith(head, "#VRML") || startsWith(head, "#X3D")) return "a VRML or X3D file";
    if (startsWith(head, "xof ")) return "a DirectX file";
    if (startsWith(head, "<")) return "an XML or HTML file";
    return "";
}

/// The size of a PLY scalar type in bytes, or 0 for a name that is not one.
int plyTypeSize(const std::string& type) {
    static const std::pair<const char*, int> sizes[] = {
        {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
        {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
        {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
    for (const auto& [name, size] : sizes)
        if (type == name) return size;
    return 0;
}

bool plyIntegerType(const std::string& type) {
    return plyTypeSize(type) != 0 && type.find("float") == std::string::npos && type != "double";
}

/// PLY: the header exactly as the format defines it, and every element's count within the caps
/// and the file's size. Debian's assimp writes past its buffers on some malformed headers (two
/// "format" lines, a property line with words left over: found by fuzz_mesh), so a header is
/// read whole here and anything the format does not define is refused before assimp sees it.
void checkPly(std::istream& in, std::uint64_t fileSize) {
    std::string line, format;
    std::uint64_t headerBytes = 0, minimumBody = 0;
    std::uint64_t elementCount = 0, elementBytes = 0;
    std::string element;
    std::vector<std::string> elements, properties;
    auto bad = [&](const std::string& why) { refuse("a PLY header " + why + ": '" + line + "'"); };
    auto closeElement = [&] {
        if (element.empty()) return;
        if (element == "vertex") checkCap(elementCount, MaxMeshVertices, "vertices");
        if (element == "face") checkCap(elementCount, MaxMeshTriangles, "faces");
        checkCap(elementCount, MaxMeshVertices + MaxMeshTriangles, "'" + element + "' elements");
        // Each entry takes at least its fixed-size properties (binary) or a byte and a line end.
        minimumBody += elementCount * (format == "ascii" ? 2 : std::max<std::uint64_t>(elementBytes, 1));
    };
    for (int lines = 0; std::getline(in, line); ++lines) {
        headerBytes += line.size() + 1;
        if (lines > 10000 || headerBytes > (1u << 20)) refuse("a PLY file whose header does not end");
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (lines == 0) continue; // "ply", checked by the caller
        std::istringstream stream(line);
        std::vector<std::string> words;
        for (std::string word; stream >> word;)
            words.push_back(word);
        const std::string key = words.empty() ? std::string() : words.front();
        if (words.empty()) continue;
        if (format.empty()) { // assimp wants it right after "ply", before any comment
            if (words.size() != 3 || words[0] != "format" || words[2] != "1.0" ||
                (words[1] != "ascii" && words[1] != "binary_little_endian" &&
                 words[1] != "binary_big_endian"))
                bad("that does not begin with a known format");
            format = words[1];
        } else if (key == "comment" || key == "obj_info") {
            continue;
        } else if (key == "format") {
            bad("with a second format line");
        } else if (key == "element") {
            closeElement();
            if (words.size() != 3) bad("with a bad element line");
            element = words[1];
            const std::string& n = words[2];
            if (n.size() > 19 || !std::all_of(n.begin(), n.end(), ::isdigit)) bad("with a bad count");
            if (std::find(elements.begin(), elements.end(), element) != elements.end())
                bad("naming an element twice");
            elements.push_back(element);
            properties.clear();
            elementCount = std::stoull(n);
            elementBytes = 0;
        } else if (key == "property") {
            if (element.empty()) bad("with a property before any element");
            const bool list = words.size() == 5 && words[1] == "list";
            if (list ? !plyIntegerType(words[2]) || plyTypeSize(words[3]) == 0
                     : words.size() != 3 || plyTypeSize(words[1]) == 0)
                bad("with a bad property line");
            if (std::find(properties.begin(), properties.end(), words.back()) != properties.end())
                bad("naming a property twice");
            properties.push_back(words.back());
            elementBytes += std::uint64_t(list ? plyTypeSize(words[2]) : plyTypeSize(words[1]));
        } else if (key == "end_header" && words.size() == 1) {
            closeElement();
            if (headerBytes + minimumBody > fileSize)
                refuse("a PLY file whose header announces more than the file holds (" + count(minimumBody) +
                       " bytes of elements at least, " + count(fileSize - std::min(fileSize, headerBytes)) +
                       " in the file)");
            return;
        } else {
            bad("with a line the format does not define");
        }
    }
    refuse("a PLY file whose header does not end");
}

/// Binary or text STL; a binary one must be exactly as long as its triangle count says.
void checkStl(const std::string& head, std::uint64_t fileSize) {
    if (fileSize >= 84) {
        std::uint32_t triangles = 0;
        for (int i = 3; i >= 0; --i)
            triangles = (triangles << 8) | std::uint8_t(head[80 + std::size_t(i)]);
        if (84 + 50 * std::uint64_t(triangles) == fileSize) {
            checkCap(triangles, MaxMeshTriangles, "triangles");
            return;
        }
        if (!startsWith(head, "solid"))
            refuse("a damaged binary STL file: its header says " + count(triangles) + " triangles (" +
                   count(84 + 50 * std::uint64_t(triangles)) + " bytes), the file has " + count(fileSize) +
                   " bytes");
    }
    if (!startsWith(head, "solid")) refuse("not an STL file (a text STL begins with 'solid')");
}

/// glTF's JSON: buffers only from data: URIs or files beside it, every count within the caps and
/// within the data it points into.
void checkGltfJson(const std::string& text, const fs::path& folder, std::uint64_t binaryChunk) {
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        refuse(std::string("a glTF file whose JSON does not parse: ") + e.what());
    }
    if (!doc.is_object() || !doc.contains("asset"))
        refuse("a JSON file that is not glTF (it has no 'asset')");
    auto sizeAt = [](const nlohmann::json& o, const char* key) -> std::uint64_t {
        if (!o.is_object() || !o.contains(key)) return 0;
        const auto& v = o[key];
        if (!v.is_number_unsigned()) refuse(std::string("a glTF file with a bad '") + key + "'");
        return v.get<std::uint64_t>();
    };
    std::vector<std::uint64_t> buffers;
    const fs::path base = fs::weakly_canonical(folder);
    for (const auto& b : doc.value("buffers", nlohmann::json::array())) {
        std::uint64_t length = sizeAt(b, "byteLength");
        if (length > MaxMeshFileBytes) refuse("a glTF buffer of " + count(length) + " bytes");
        if (b.is_object() && b.contains("uri")) {
            if (!b["uri"].is_string()) refuse("a glTF buffer with a bad 'uri'");
            const std::string uri = b["uri"].get<std::string>();
            if (uri.rfind("data:", 0) == 0) {
                if (length > uri.size()) refuse("a glTF data: buffer shorter than its byteLength");
            } else {
                const fs::path p = fs::weakly_canonical(folder / uri);
                auto [end, _] = std::mismatch(base.begin(), base.end(), p.begin(), p.end());
                if (fs::path(uri).is_absolute() || end != base.end())
                    refuse("a glTF buffer '" + uri + "' outside the mesh's folder");
                std::error_code ec;
                const std::uint64_t actual = fs::file_size(p, ec);
                if (ec) refuse("a glTF buffer '" + uri + "' that cannot be read");
                if (length > actual) refuse("a glTF buffer '" + uri + "' shorter than its byteLength");
            }
        } else if (length > binaryChunk) {
            refuse("a GLB whose buffer is longer than its binary chunk");
        }
        buffers.push_back(length);
    }
    std::vector<std::uint64_t> views;
    for (const auto& v : doc.value("bufferViews", nlohmann::json::array())) {
        const std::uint64_t buffer = sizeAt(v, "buffer"), offset = sizeAt(v, "byteOffset"),
                            length = sizeAt(v, "byteLength");
        if (buffer >= buffers.size() || offset > buffers[buffer] || length > buffers[buffer] - offset)
            refuse("a glTF bufferView outside its buffer");
        views.push_back(length);
    }
    for (const auto& a : doc.value("accessors", nlohmann::json::array())) {
        const std::uint64_t n = sizeAt(a, "count");
        checkCap(n, 3 * MaxMeshTriangles, "elements in an accessor");
        if (a.is_object() && a.contains("bufferView")) {
            const std::uint64_t view = sizeAt(a, "bufferView");
            if (view >= views.size()) refuse("a glTF accessor of a bufferView that does not exist");
            // Every element takes a byte at least.
            if (n > views[view])
                refuse("a glTF accessor of " + count(n) + " elements in a bufferView of " +
                       count(views[view]) + " bytes");
        }
    }
}

} // namespace

bool isAllowedImporterExtension(const std::string& extension) {
    return extension == "obj" || extension == "stl" || extension == "ply" || extension == "gltf" ||
           extension == "glb";
}

MeshFormat checkMeshFile(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) refuse(std::string("cannot read: ") + std::strerror(errno));
    std::error_code ec;
    const std::uint64_t fileSize = fs::file_size(file, ec);
    if (ec) refuse("cannot read: " + ec.message());
    if (fileSize > MaxMeshFileBytes)
        refuse("a file of " + count(fileSize) + " bytes (meshes are read up to 1 GiB)");
    std::string head(4096, '\0');
    in.read(head.data(), std::streamsize(head.size()));
    head.resize(std::size_t(in.gcount()));
    const std::string ext = lowerExtension(file);
    const fs::path folder = fs::absolute(fs::path(file)).parent_path();

    if (startsWith(head, "glTF")) {
        // GLB: a 12-byte header, then the JSON chunk and an optional binary chunk.
        auto u32 = [&](std::size_t at) {
            std::uint32_t v = 0;
            for (int i = 3; i >= 0; --i)
                v = (v << 8) | std::uint8_t(head[at + std::size_t(i)]);
            return v;
        };
        if (head.size() < 20) refuse("a damaged GLB file (too short)");
        if (u32(8) != fileSize) refuse("a damaged GLB file (its header says " + count(u32(8)) + " bytes)");
        const std::uint64_t jsonLength = u32(12);
        if (jsonLength > MaxGltfJsonBytes || 20 + jsonLength > fileSize)
            refuse("a damaged GLB file (its JSON chunk)");
        std::string json(jsonLength, '\0');
        in.clear();
        in.seekg(20);
        in.read(json.data(), std::streamsize(jsonLength));
        const std::uint64_t rest = fileSize - 20 - jsonLength;
        checkGltfJson(json, folder, rest >= 8 ? rest - 8 : 0);
        return MeshFormat::Glb;
    }
    if (startsWith(head, "ply\n") || startsWith(head, "ply\r\n")) {
        in.clear();
        in.seekg(0);
        checkPly(in, fileSize);
        return MeshFormat::Ply;
    }
    if (ext == ".stl") {
        checkStl(head, fileSize);
        return MeshFormat::Stl;
    }
    const std::size_t firstText = head.find_first_not_of(" \t\r\n\xef\xbb\xbf");
    if (ext == ".gltf" || (firstText != std::string::npos && head[firstText] == '{')) {
        if (fileSize > MaxGltfJsonBytes) refuse("a glTF file of " + count(fileSize) + " bytes of JSON");
        std::string json(fileSize, '\0');
        in.clear();
        in.seekg(0);
        in.read(json.data(), std::streamsize(fileSize));
        checkGltfJson(json, folder, 0);
        return MeshFormat::Gltf;
    }
    const std::string other = otherKind(head);
    if (!other.empty()) refuse(other + ": meshes must be OBJ, STL, PLY or glTF");
    if (ext == ".obj") {
        if (head.find('\0') != std::string::npos) refuse("an OBJ file that is not text");
        // OBJ announces nothing: its vertices and faces are counted before assimp reads them.
        in.clear();
        in.seekg(0);
        std::uint64_t vertices = 0, faces = 0;
        for (std::string line; std::getline(in, line);) {
            const std::size_t at = line.find_first_not_of(" \t");
            if (at == std::string::npos || at + 1 >= line.size()) continue;
            if (line[at] == 'v' && (line[at + 1] == ' ' || line[at + 1] == '\t')) ++vertices;
            if (line[at] == 'f' && (line[at + 1] == ' ' || line[at + 1] == '\t')) ++faces;
        }
        checkCap(vertices, MaxMeshVertices, "vertices");
        checkCap(faces, MaxMeshTriangles, "faces");
        return MeshFormat::Obj;
    }
    refuse("a file of a kind Marbler does not read: meshes must be OBJ, STL, PLY or glTF (.obj, .stl, .ply, "
           ".gltf, .glb)");
}

} // namespace marbler::gl::detail
