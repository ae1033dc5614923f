#pragma once
/// A design on an object, a solid one carved from its block or a flat one laid on the object's
/// texture coordinates (FlatOnUvs, Bake.h): how it is seen (MeshSettings: size, object, orbit camera,
/// framing, cut), the camera that frames an object in the design box (frameObject), and the
/// CPU's own object path: the object rasterised on the CPU into the same G-buffer the GL pass
/// reads back (rasterizeObject), then coloured by the kernel (shadeMeshOnCpu). So an object
/// renders with no display and no GL, as every verb must; the GL back end
/// (gl/GlRenderer.h) draws the same object with the same camera.

#include "marbler/CpuRenderer.h"
#include "marbler/Genome.h"
#include "marbler/Mesh.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace marbler {

/// A cutting plane through a solid object: points with dot(normal, p) > offset (in the fitted
/// design box) are cut away, showing the marbled inside.
struct CutPlane {
    glm::dvec3 normal{0.0, 0.0, 1.0};
    double offset = 0.0;
};

/// How a design is shown on an object.
struct MeshSettings {
    int width = 512, height = 512;
    std::string mesh = DefaultMesh; ///< a built-in name (builtinMeshNames()) or a file path
    /// Orbit camera about the design box centre, +y up: the eye sits at
    /// centre + D * (cos pitch sin yaw, sin pitch, cos pitch cos yaw), looking at the centre.
    double yaw = 30.0, pitch = 20.0; ///< degrees
    /// D in units of the fitted object's bounding radius about the box centre. 0 (the default):
    /// framed, so the object fills the view at any angle and aspect: D is the nearest distance
    /// that keeps every vertex in view, and the view is then shifted and scaled (an off-centre
    /// frustum) so the object's projected bounds are centred and span 92 % of the view's width
    /// or height.
    double distance = 0.0;
    double fovY = 50.0; ///< vertical field of view before the framing and the zoom, degrees
    /// Magnification of the image about the view's centre (the framed object's centre), by
    /// narrowing the frustum: the eye stays where it is, outside the object.
    double zoom = 1.0;
    bool lighting = true; ///< false: the marbling's own colours, unlit (tests, flat previews)
    int supersample = 3;  ///< 1, 3 or 5 (n x n)
    std::optional<CutPlane> cut;
    Color clearColor{0x2b, 0x2b, 0x2b};
    int threads = 0; ///< CPU workers where the CPU rasterises or shades; 0: every core
};

/// The largest output side of an object render (the G-buffer is n times larger).
inline constexpr int MaxMeshSide = 8192;

/// The first pass of an object render: per sample of the n x n supersampled raster (width * n
/// by height * n, rows bottom to top as GL reads them), where the object is seen, for a caller
/// that colours the samples itself (the CPU kernel).
struct MeshGBuffer {
    int width = 0, height = 0; ///< the output raster
    int supersample = 1;       ///< n
    /// 4 floats a sample: the design point relative to `reference`, and w = 1 where the object
    /// covers the sample (0: the clear colour).
    std::vector<float> positions;
    /// 4 floats a sample: the unit normal facing the way the shading takes it, w = 0.
    std::vector<float> normals;
    /// 2 floats a sample: the texture coordinates there (flat designs only; empty for solids).
    std::vector<float> uvs;
    glm::dvec3 reference{0.0}; ///< the design box centre
    glm::dvec3 eye{0.0};       ///< the camera, relative to `reference`
    glm::dvec3 light{0.0};     ///< unit direction towards the key light
};

/// The checks of an object render's settings (the size, supersampling, camera and cut);
/// returns the cutting plane's unit normal and offset (0 without a cut). Throws
/// InputError naming what is wrong.
void checkMeshSettings(const MeshSettings& settings, glm::dvec3& cutNormal, double& cutOffset);

/// An object's vertices about its bounding-box centre, in its own units: what framing needs.
struct FittedMesh {
    glm::dvec3 centre{0.0};  ///< the bounding box's centre
    glm::dvec3 boxSize{0.0}; ///< the bounding box's size
    double radius = 0.0;     ///< the farthest vertex from the centre
    std::vector<glm::dvec3> points;
};

/// `mesh`'s vertices about its bounding-box centre.
FittedMesh fitMesh(const MeshData& mesh);

/// The box an object is fitted into: a solid design's own block; for a flat design, a cube as
/// wide as the design's longer side (only its texture coordinates meet the design).
glm::dvec3 objectBox(const Genome& genome);

/// Whether `mesh` has texture coordinates of its own, one a vertex (not bake's generated
/// patches, uvsArePatches), on which a flat design can lie.
bool hasOwnUvs(const MeshData& mesh);

/// Throws InputError, naming `meshName`, when a flat design is to be shown on a mesh without
/// its own texture coordinates (`meshHasOwnUvs` false); does nothing for a solid design.
void checkFlatDesignFits(const Genome& genome, bool meshHasOwnUvs, const std::string& meshName);

/// Where the camera and the key light are for an object fitted into a design box: the largest
/// uniform scale that keeps the object inside the box, centred in it, seen from the orbit camera
/// of `settings` (framed when its distance is 0).
struct ObjectCamera {
    double scale = 1.0;             ///< the fitted mesh's units (about its centre) to design units
    glm::dvec3 reference{0.0};      ///< the design box centre
    glm::dvec3 eye{0.0};            ///< the camera, relative to `reference`
    glm::dvec3 light{0.0};          ///< unit direction towards the key light
    glm::dmat4 viewProjection{1.0}; ///< design space relative to `reference` to clip space
};

/// The camera for `mesh` (fitMesh) in a design box of `designSize` seen as `settings` says.
ObjectCamera frameObject(const glm::dvec3& designSize, const FittedMesh& mesh, const MeshSettings& settings);

/// Pass 1 on the CPU: `mesh` rasterised with the camera of frameObject into the G-buffer the GL
/// pass makes (depth-tested, the cut's cap and the inside of open meshes as the GL shader
/// gives them), on every core. A solid design's object is fitted into its design box; a flat
/// design's into a cube as wide as the design's longer side, with the texture coordinates at
/// every sample (the mesh must have its own: not uvsArePatches). Throws InputError for bad
/// settings (checkMeshSettings), a broken mesh, or a flat design on a mesh without its own UVs.
MeshGBuffer rasterizeObject(const Genome& genome, const MeshData& mesh, const MeshSettings& settings,
                            const RenderControl* control = nullptr);

/// The second pass of an object render on the CPU: the colour rule at each covered sample of
/// `gbuffer` (a flat design's at the sample's texture point, FlatOnUvs, the background beyond
/// the design), lit as the GL shading pass lights it (unless `settings.lighting` is off), averaged
/// in linear light with `settings.clearColor` where the object does not cover a sample. Agrees
/// with the GL shading up to the GPU's float rounding. Runs on every core. Throws InputError for
/// a colour index outside the palette, Cancelled when cancelled.
Image shadeMeshOnCpu(const Genome& genome, const MeshGBuffer& gbuffer, const MeshSettings& settings,
                     const RenderControl* control = nullptr);

/// Both passes on the CPU: a design on `mesh` with no GL at all.
Image renderObjectOnCpu(const Genome& genome, const MeshData& mesh, const MeshSettings& settings,
                        const RenderControl* control = nullptr);

} // namespace marbler
