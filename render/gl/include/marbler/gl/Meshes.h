#pragma once
/// Objects to marble: the built-in meshes, generated in code, and user meshes read with assimp.

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace marbler::gl {

/// An indexed triangle mesh with per-vertex normals.
struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> indices; ///< three per triangle
};

/// The built-in objects: sphere, cube, torus, vase, teapot.
std::vector<std::string> builtinMeshNames();

/// A built-in object (+y up, about unit size). Throws InputError for an unknown name.
MeshData builtinMesh(const std::string& name);

/// Reads OBJ, STL, PLY, glTF and whatever else assimp knows, every mesh of the scene merged
/// with its node transforms applied. Throws InputError naming the file and assimp's message
/// when it cannot be read or holds no triangles.
MeshData loadMesh(const std::string& file);

/// A built-in name or else a file path.
MeshData meshByNameOrFile(const std::string& nameOrFile);

} // namespace marbler::gl
