#pragma once
/// Baking a design onto an object for other 3D tools: the colour rule evaluated at the surface
/// point behind every texel of the object's texture (its UV map, generated when it has none),
/// and the object written with that texture as glTF 2.0 or OBJ.

#include "marbler/CpuRenderer.h"
#include "marbler/Genome.h"
#include "marbler/Mesh.h"

#include <glm/vec3.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace marbler {

/// The largest texture side `bake` makes (16384² RGB is 768 MiB, and the texel owners as much).
inline constexpr int MaxBakeTexture = 16384;

/// Where a mesh sits in the design space, exactly as the window places it: its bounding box
/// centred in the design box and scaled uniformly by the largest factor that keeps it inside.
/// A flat (2D) design is projected onto the object along z (a planar projection): the mesh's
/// x-y bounds fitted into the design's rectangle, +y up on screen, so seen from the front (+z)
/// the design stands upright; surfaces parallel to z show it stretched into streaks.
struct MeshPlacement {
    glm::dvec3 meshCentre{0.0}; ///< the mesh's bounding-box centre, in its own units
    glm::dvec3 designCentre{0.0};
    double scale = 1.0;
    bool planar = false; ///< 2D: design (x, y) = centre + scale * (x, -y)
    /// The design point of a point of the mesh (in the mesh's units).
    glm::dvec3 designPoint(const glm::dvec3& meshPoint) const;
};
MeshPlacement placeMesh(const Genome& genome, const MeshData& mesh);

/// Where a flat design lies on an object's own texture coordinates: its rectangle fitted into
/// the texture's unit square by its longer side, keeping its aspect and centred across the
/// shorter one (whose two bands beyond the design show the background), +y downwards as in
/// both. So a flat design baked onto the book or the vase is the design itself, not a projection.
struct FlatOnUvs {
    explicit FlatOnUvs(const Genome& genome);
    glm::dvec2 size;   ///< the design's width and height
    double side;       ///< the design length across the whole texture
    glm::dvec2 origin; ///< the design point at UV (0, 0)
    /// The design point (z = 0) at texture coordinates `uv`.
    glm::dvec3 designPoint(const glm::dvec2& uv) const;
    /// Whether a design point lies within the design's rectangle.
    bool inside(const glm::dvec3& q) const;
};

/// Texture coordinates in which no two triangles overlap, with a gutter of 1.5 texels or more
/// round each patch: the mesh with every triangle's vertices of its own (positions and normals
/// copied), consecutive triangles paired into the square cells of a grid, each pair the two
/// halves of its cell on either side of the diagonal. A pair that shares an edge (a quad) shares
/// the diagonal, so the texture runs on across that edge; any other pair is drawn apart from it.
/// Honest and simple: no texel serves two points of the surface; the price is a seam round
/// every cell and texels stretched where a quad is far from a square. Throws InputError when
/// the triangles are too many for the texture (a side under 3 texels). The result is marked
/// MeshData::uvsArePatches, so a flat design is still projected onto it along z.
MeshData withGeneratedUvs(const MeshData& mesh, int textureSize);

/// Whether the mesh has texture coordinates that can be baked into: one per vertex, all within
/// [0, 1] (tiled or mirrored coordinates would give one texel several surface points).
bool hasUsableUvs(const MeshData& mesh);

/// What a bake does besides the genome and the mesh.
struct BakeSettings {
    int textureSize = 2048;
    /// Samples a texel, the render patterns (genome-format.md) laid over the texel's square in
    /// UV space; each sample is moved onto the texel's triangle, so it lies on the surface.
    std::string aa = "rgss";
    /// Texels beyond the triangles' edges given their neighbours' colours, so that filtering
    /// across a UV seam never reaches the background.
    int dilation = 4;
    int threads = 0; ///< 0: every core
};

/// A baked texture: rows top to bottom (v = (row + 0.5) / size at texel centres), the texels
/// outside every triangle and the dilation showing the genome's background.
struct BakedTexture {
    Image image;
    std::size_t coveredTexels = 0; ///< texels whose centre lies in a triangle
};

/// Evaluates the design at the surface point behind each texel whose centre lies in a triangle
/// of `mesh` in UV space (the first triangle in index order where triangles overlap), on every
/// core, then dilates. A flat design on a mesh's own UVs (not uvsArePatches) is evaluated at
/// the texel's point of the design instead (FlatOnUvs). `mesh` must have UVs (hasUsableUvs).
/// Throws InputError for bad settings, a genome with a source image, or a mesh without usable
/// UVs; Cancelled when cancelled.
BakedTexture bakeTexture(const Genome& genome, const MeshData& mesh, const BakeSettings& settings,
                         const RenderControl* control = nullptr);

/// Writes the mesh (positions in its own units, its normals and UVs) and its texture, by the
/// extension of `file`: `.glb` (glTF 2.0 binary, the PNG inside), `.gltf` (with NAME.bin and
/// NAME.png beside it) or `.obj` (with NAME.mtl and NAME.png). Every file is written under a
/// temporary name and renamed only when all are complete, so a failure leaves none behind.
/// Returns the files written, `file` last. Throws InputError for another extension or a mesh
/// without UVs, RuntimeFailure for I/O failures.
std::vector<std::filesystem::path> writeTexturedMesh(const MeshData& mesh, const Image& texture,
                                                     const std::filesystem::path& file,
                                                     const std::string& name = "marbled");

/// The extensions writeTexturedMesh writes, with their dots.
std::vector<std::string> texturedMeshExtensions();

} // namespace marbler
