#pragma once
/// Triangle meshes to marble: the built-in objects, generated in code so that the headless verbs
/// have them without assimp (mesh files are read by the GL back end, marbler/gl/Meshes.h).

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace marbler {

/// An indexed triangle mesh with per-vertex normals and, optionally, texture coordinates.
struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    /// One per vertex, or empty when the mesh has none. Image convention: (0, 0) is the top-left
    /// corner of the texture and v grows downwards (as in glTF; OBJ and assimp count v upwards).
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices; ///< three per triangle
    /// Whether the UVs are a mosaic of patches made for baking (withGeneratedUvs) rather than
    /// the object's own: a flat design is then projected onto the object, not laid on its UVs.
    bool uvsArePatches = false;
};

/// The built-in objects, in the order the window lists them: vase (the default), sphere, cube,
/// torus, teapot, and those a textile or stationery designer shows a pattern on: book, cushion,
/// cloth (hanging in folds), wall. The one list of them: `--mesh`, the window's object boxes and the session
/// file all read it.
std::vector<std::string> builtinMeshNames();

/// The object a solid design is shown on until a person picks another.
inline constexpr const char* DefaultMesh = "vase";

/// The built-in names for a message: "vase, sphere, cube, torus, teapot".
std::string builtinMeshList();

/// Whether `name` is one of builtinMeshNames().
bool isBuiltinMesh(const std::string& name);

/// A built-in object (+y up, about unit size) with its natural texture coordinates, no two
/// triangles overlapping in them and none wrapping round a seam: the vase, the sphere (by
/// longitude and latitude) and the torus (by its two angles) round and up over the whole
/// texture, the seam at the back (-z), the texture's middle facing the front (+z); the cube by
/// faces, six tiles; the teapot by parts; the book as its jacket lies flat (back cover, spine,
/// front cover across the middle, undistorted) with its page edges in strips above and below;
/// the cushion's face, the cloth and the wall upright across the texture, undistorted. Seen from outside
/// every texture reads the right way round, unmirrored. Throws InputError for an unknown name.
MeshData builtinMesh(const std::string& name);

} // namespace marbler
