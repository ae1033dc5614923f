#pragma once
/// Internal to marbler_gl: what a mesh file must be before assimp sees it. A mesh file travels
/// with designs and sessions, so it may come from a stranger: only OBJ, STL, PLY and glTF/GLB
/// are read, told by the file's content (OBJ, which has none, by its name and being text), and
/// the counts a header announces are checked against caps and against the file's own size
/// before anything is allocated for them.

#include <cstdint>
#include <string>

namespace marbler::gl::detail {

/// The formats read, each by its own assimp importer only.
enum class MeshFormat { Obj, Stl, Ply, Gltf, Glb };

/// Caps on what a mesh may hold: far more than any object shown in a 3 x 3 grid needs.
inline constexpr std::uint64_t MaxMeshVertices = 16'000'000;
inline constexpr std::uint64_t MaxMeshTriangles = 32'000'000;
/// The largest mesh file read (and the largest glTF JSON parsed whole).
inline constexpr std::uint64_t MaxMeshFileBytes = std::uint64_t(1) << 30;
inline constexpr std::uint64_t MaxGltfJsonBytes = std::uint64_t(64) << 20;

/// Reads the file's head (and a glTF's JSON) and says its format. Throws InputError("what is
/// wrong") without the file's name (the caller adds it) when the file cannot be read, is of
/// another kind ("a Collada file: meshes must be OBJ, STL, PLY or glTF"), or announces more
/// than the caps or than the file holds.
MeshFormat checkMeshFile(const std::string& file);

/// The file extensions of the assimp importers allowed for meshes.
bool isAllowedImporterExtension(const std::string& extension);

} // namespace marbler::gl::detail
