#pragma once
/// Objects to marble: the built-in meshes (marbler/Mesh.h, generated in code) and user meshes read
/// with assimp.

#include "marbler/Mesh.h"

#include <string>

namespace marbler::gl {

using marbler::builtinMesh;
using marbler::builtinMeshNames;
using marbler::MeshData;

/// Reads OBJ, STL, PLY, glTF and whatever else assimp knows, every mesh of the scene merged
/// with its node transforms applied, with the first set of texture coordinates when every mesh
/// of the scene has one (else none). Throws InputError naming the file and assimp's message
/// when it cannot be read or holds no triangles.
MeshData loadMesh(const std::string& file);

/// A built-in name or else a file path.
MeshData meshByNameOrFile(const std::string& nameOrFile);

} // namespace marbler::gl
