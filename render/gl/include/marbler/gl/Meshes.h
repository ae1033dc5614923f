#pragma once
/// Objects to marble: the built-in meshes (marbler/Mesh.h, generated in code) and user meshes read
/// with assimp.

#include "marbler/Mesh.h"

#include <string>

namespace marbler::gl {

using marbler::builtinMesh;
using marbler::builtinMeshNames;
using marbler::MeshData;

/// Reads OBJ, STL, PLY and glTF/GLB, and nothing else (a file is told by its content, OBJ by
/// its name and being text; the counts its header announces are checked against caps and the
/// file's size before assimp reads it, with only those formats' importers), every mesh of the
/// scene merged with its node transforms applied, with the first set of texture coordinates
/// when every mesh of the scene has one (else none). Throws InputError naming the file and what
/// is wrong when it is of another kind, too large, cannot be read or holds no triangles.
MeshData loadMesh(const std::string& file);

/// A built-in name or else a file path.
MeshData meshByNameOrFile(const std::string& nameOrFile);

} // namespace marbler::gl
