#include "marbler/gl/GlRenderer.h"

#include "GlContext.h"
#include "GlProgram.h"
#include "OpPacking.h"
#include "marbler/Bake.h"
#include "marbler/Error.h"
#include "marbler/SourceDecoder.h"
#include "marbler/Tools.h"
#include "marbler/gl/Backend.h"
#include "marbler/gl/Meshes.h"
#include "marbler/gl/ShaderSource.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QOpenGLFunctions_4_3_Core>
#include <QOpenGLVersionFunctionsFactory>
#include <QSurfaceFormat>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>

namespace marbler::gl {
namespace {

using detail::ContextParts;
using detail::LiveRenderers;
using detail::liveRenderers;
using detail::makeContext;
using detail::registerExitHandler;

/// Largest tile of a raster render: small enough to keep one draw call well below a desktop
/// driver's watchdog for long genomes, large enough that tiles cost nothing extra.
constexpr int MaxTileSide = 2048;
/// Colour-rule evaluations (pixels x samples x operations) one draw may take before the tile
/// is made smaller, for the same watchdog.
constexpr double MaxWorkPerDraw = 4e9;
/// Samples of the largest antialiasing pattern (grid8); the shaders' uniform arrays hold this.
constexpr int MaxSamples = 64;

glm::vec3 linearColor(Color c) {
    return {float(srgbToLinear(c.r / 255.0)), float(srgbToLinear(c.g / 255.0)),
            float(srgbToLinear(c.b / 255.0))};
}

/// The G-buffer's GL objects, freed together: positions, normals and (a flat design's only)
/// texture coordinates.
struct GBufferTargets {
    QOpenGLFunctions_4_3_Core* gl = nullptr;
    GLuint textures[3] = {0, 0, 0}, depth = 0, fbo = 0;
    explicit GBufferTargets(QOpenGLFunctions_4_3_Core* functions)
        : gl(functions) {}
    GBufferTargets(const GBufferTargets&) = delete;
    GBufferTargets& operator=(const GBufferTargets&) = delete;
    ~GBufferTargets() {
        gl->glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (fbo) gl->glDeleteFramebuffers(1, &fbo);
        if (depth) gl->glDeleteRenderbuffers(1, &depth);
        gl->glDeleteTextures(3, textures);
    }
};

/// The version-2 switches of a shader variant (tools.glsl): the forms of stretch, flow and a
/// finite core, the bleed rule and version 3's stylus (0 none, 1 one tine, 2 rakes: stylusForm).
/// A design without them runs the version-1 code.
struct Features {
    bool version2 = false, bleed = false;
    int stylus = 0;
    int index() const { return (version2 ? 1 : 0) + (bleed ? 2 : 0) + 4 * stylus; }
};

Features featuresOf(const Genome& genome, const std::vector<PreparedOp>& ops) {
    return {needsVersion2Forms(ops), genome.bleed > 0.0, stylusForm(ops)};
}

} // namespace

struct GlRenderer::Impl {
    ContextParts parts;
    QOpenGLFunctions_4_3_Core* gl = nullptr;
    GlProgram raster[48]; // by dimension, source image and features (buildRaster)
    GlProgram gbuffer;
    GlProgram mesh[48]; // by dimension, source image and features (buildShading)
    GLuint emptyVao = 0;
    GLuint opBuffer = 0;
    GLuint opTexture = 0; // the buffer texture over opBuffer
    GLuint teethBuffer = 0;
    GLuint teethTexture = 0; // the buffer texture over teethBuffer
    GLuint pathsBuffer = 0;
    GLuint pathsTexture = 0; // the buffer texture over pathsBuffer
    GLuint sourceTexture = 0;

    // The last mesh, kept on the GPU: re-rendering from another angle uploads nothing.
    std::string meshName;
    GLuint meshVao = 0, meshVbo = 0, meshIbo = 0;
    GLsizei meshIndexCount = 0;
    /// The vertices relative to the box centre (before the fit's scale), for framing.
    FittedMesh meshFit;
    bool meshHasOwnUvs = false; ///< hasOwnUvs: a flat design can lie on the mesh

    void makeCurrent() {
        if (!parts.context->makeCurrent(parts.surface.get()))
            throw RuntimeFailure("GL: the context cannot be made current");
    }

    GLint limit(GLenum name) const {
        GLint value = 0;
        gl->glGetIntegerv(name, &value);
        return value;
    }

    /// The shared shader source with the variant's switches after its #version line: the
    /// dimension (a flat design never pays for the volume law's cube root), whether a source
    /// image is sampled and the version-2 features. 48 raster variants at most, each compiled
    /// on first use, so compiling costs nothing per genome.
    static std::string withDefines(std::string source, int dimension, bool hasSource, Features features) {
        std::string defines = "#define MARBLER_DIMENSION " + std::to_string(dimension) +
                              "\n#define MARBLER_HAS_SOURCE " + (hasSource ? "1" : "0") +
                              "\n#define MARBLER_VERSION2 " + (features.version2 ? "1" : "0") +
                              "\n#define MARBLER_BLEED " + (features.bleed ? "1" : "0") +
                              "\n#define MARBLER_STYLUS " + std::to_string(features.stylus) + "\n";
        source.insert(source.find('\n') + 1, defines);
        return source;
    }

    GlProgram& buildRaster(int dimension, bool hasSource, Features features) {
        GlProgram& program = raster[(dimension == 3 ? 2 : 0) + (hasSource ? 1 : 0) + 4 * features.index()];
        if (!program.id())
            program = GlProgram(*gl, "raster",
                                {{GL_VERTEX_SHADER, assembledShader("fullscreen.vert")},
                                 {GL_FRAGMENT_SHADER, withDefines(assembledShader("raster.frag"), dimension,
                                                                  hasSource, features)}});
        return program;
    }

    void buildMesh() {
        if (!gbuffer.id())
            gbuffer = GlProgram(*gl, "gbuffer",
                                {{GL_VERTEX_SHADER, assembledShader("gbuffer.vert")},
                                 {GL_FRAGMENT_SHADER, assembledShader("gbuffer.frag")}});
    }

    /// Pass 2 of a mesh render, the colour rule per sample: at the sample's point of a solid, or
    /// at its texture point of a flat design (dimension 2, with its source image if it has one).
    GlProgram& buildShading(int dimension, bool hasSource, Features features) {
        GlProgram& program = mesh[(dimension == 3 ? 2 : 0) + (hasSource ? 1 : 0) + 4 * features.index()];
        if (!program.id())
            program = GlProgram(*gl, "mesh",
                                {{GL_VERTEX_SHADER, assembledShader("fullscreen.vert")},
                                 {GL_FRAGMENT_SHADER, withDefines(assembledShader("mesh.frag"), dimension,
                                                                  hasSource, features)}});
        return program;
    }

    /// A flat design's source image on unit 2, decoded by the CPU renderer's own decoder: the
    /// same pixels in linear light, the same refusals.
    void bindSource(const Genome& genome) {
        const LinearRaster image = decodeSourceImage(genome);
        if (!sourceTexture) gl->glGenTextures(1, &sourceTexture);
        gl->glActiveTexture(GL_TEXTURE2);
        gl->glBindTexture(GL_TEXTURE_2D, sourceTexture);
        gl->glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        gl->glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        // Linear floats, filtered as they are: bilinear in linear light, as the spec asks (and
        // values beyond 1 from a linear image are kept, as the CPU keeps them); clamping to the
        // edge texels is the spec's rule within the design space.
        gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, image.width, image.height, 0, GL_RGB, GL_FLOAT,
                         image.rgb.data());
        gl->glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        gl->glActiveTexture(GL_TEXTURE0);
    }

    /// The genome's operations relative to `reference` into the storage buffer, and the inks,
    /// into the uniforms of `program` (current).
    void uploadGenome(const GlProgram& program, const std::vector<PreparedOp>& ops, const Genome& genome,
                      const glm::dvec3& reference) {
        PackedOps packedOps = packOps(ops, reference);
        std::vector<float>& packed = packedOps.records;
        std::vector<float>& teeth = packedOps.teeth;
        std::vector<float>& paths = packedOps.paths;
        if (packed.empty()) packed.assign(PackedOpFloats, 0.0f); // a bound buffer may not be empty
        if (teeth.empty()) teeth.assign(1, 0.0f);
        if (paths.empty()) paths.assign(4, 0.0f);
        const auto texels = std::size_t(limit(GL_MAX_TEXTURE_BUFFER_SIZE));
        if (packed.size() / 4 > texels || teeth.size() > texels)
            throw RuntimeFailure("GL: " + std::to_string(ops.size()) +
                                 " operations exceed this driver's buffer texture limit");
        if (paths.size() / 4 > texels)
            throw RuntimeFailure("GL: the stylus paths' " +
                                 std::to_string(paths.size() / 4 / StylusSegmentTexels) +
                                 " segments exceed this driver's buffer texture limit of " +
                                 std::to_string(texels / StylusSegmentTexels));
        // Unit 3 holds the records, unit 4 the teeth and unit 5 the stylus paths: 0 and 1 hold
        // the mesh G-buffer, 2 the source image.
        auto bindBuffer = [this](GLuint buffer, GLuint texture, GLenum unit, GLenum format,
                                 const std::vector<float>& data) {
            gl->glBindBuffer(GL_TEXTURE_BUFFER, buffer);
            gl->glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(),
                             GL_STREAM_DRAW);
            gl->glBindBuffer(GL_TEXTURE_BUFFER, 0);
            gl->glActiveTexture(unit);
            gl->glBindTexture(GL_TEXTURE_BUFFER, texture);
            gl->glTexBuffer(GL_TEXTURE_BUFFER, format, buffer);
        };
        bindBuffer(opBuffer, opTexture, GL_TEXTURE3, GL_RGBA32F, packed);
        bindBuffer(teethBuffer, teethTexture, GL_TEXTURE4, GL_R32F, teeth);
        bindBuffer(pathsBuffer, pathsTexture, GL_TEXTURE5, GL_RGBA32F, paths);
        gl->glActiveTexture(GL_TEXTURE0);
        gl->glUniform1i(program.uniform("uOps"), 3);
        gl->glUniform1i(program.uniform("uTeeth"), 4);
        gl->glUniform1i(program.uniform("uPaths"), 5);
        gl->glUniform1i(program.uniform("uOpCount"), GLint(ops.size()));
        gl->glUniform1f(program.uniform("uBleed"), float(genome.bleed));
        // A wrapping bath (docs/genome-format.md): the periods and their inverses, else 0.
        const bool wraps = genome.wrap && genome.dimension == 2;
        gl->glUniform4f(program.uniform("uWrap"), wraps ? float(genome.size.x) : 0.0f,
                        wraps ? float(genome.size.y) : 0.0f, wraps ? float(1.0 / genome.size.x) : 0.0f,
                        wraps ? float(1.0 / genome.size.y) : 0.0f);
        // Its lattice: the shift one period brings across it (Tools.h PreparedOp::wrapShift).
        gl->glUniform2f(program.uniform("uWrapShift"),
                        wraps && genome.lattice == Lattice::Brick ? float(0.5 * genome.size.x) : 0.0f,
                        wraps && genome.lattice == Lattice::HalfDrop ? float(0.5 * genome.size.y) : 0.0f);
        std::vector<float> inks(17 * 3, 0.0f);
        for (std::size_t k = 0; k < genome.palette.size() && k < 16; ++k) {
            glm::vec3 c = linearColor(genome.palette[k]);
            std::copy_n(&c.x, 3, &inks[k * 3]);
        }
        glm::vec3 background = linearColor(genome.background);
        std::copy_n(&background.x, 3, &inks[16 * 3]);
        gl->glUniform3fv(program.uniform("uInk"), 17, inks.data());
        glm::vec3 ref(reference);
        gl->glUniform3fv(program.uniform("uReference"), 1, &ref.x);
        gl->glUniform2f(program.uniform("uDesignSize"), float(genome.size.x), float(genome.size.y));
    }

    /// An RGBA8UI colour target with a framebuffer around it.
    void makeTarget(int width, int height, GLuint& fbo, GLuint& texture) {
        gl->glGenTextures(1, &texture);
        gl->glBindTexture(GL_TEXTURE_2D, texture);
        gl->glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8UI, width, height);
        gl->glGenFramebuffers(1, &fbo);
        gl->glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
        checkFramebuffer("colour target");
    }

    void checkFramebuffer(const char* what) {
        GLenum status = gl->glCheckFramebufferStatus(GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE)
            throw RuntimeFailure(std::string("GL: the ") + what + " framebuffer is incomplete (status 0x" +
                                 std::to_string(status) + ")");
    }

    void checkErrors(const char* where) {
        GLenum error = gl->glGetError();
        if (error != GL_NO_ERROR)
            throw RuntimeFailure(std::string("GL error ") + std::to_string(error) + " in " + where);
    }

    void loadMeshToGpu(const std::string& name) {
        if (name == meshName && meshVao) return;
        MeshData data = meshByNameOrFile(name);
        meshFit = fitMesh(data);
        meshHasOwnUvs = hasOwnUvs(data);
        std::vector<float> vertices;
        vertices.reserve(data.positions.size() * VertexFloats);
        for (std::size_t v = 0; v < data.positions.size(); ++v) {
            const glm::dvec3& p = meshFit.points[v]; // about the box centre, fitted later by a uniform scale
            glm::vec3 n = data.normals[v];
            float len = glm::length(n);
            n = len > 0.0f ? n / len : glm::vec3(0, 1, 0);
            const glm::vec2 uv = meshHasOwnUvs ? data.uvs[v] : glm::vec2(0.0f);
            vertices.insert(vertices.end(), {float(p.x), float(p.y), float(p.z), n.x, n.y, n.z, uv.x, uv.y});
        }
        if (!meshVao) {
            gl->glGenVertexArrays(1, &meshVao);
            gl->glGenBuffers(1, &meshVbo);
            gl->glGenBuffers(1, &meshIbo);
        }
        gl->glBindVertexArray(meshVao);
        gl->glBindBuffer(GL_ARRAY_BUFFER, meshVbo);
        gl->glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(),
                         GL_STATIC_DRAW);
        gl->glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, meshIbo);
        gl->glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(data.indices.size() * sizeof(std::uint32_t)),
                         data.indices.data(), GL_STATIC_DRAW);
        const GLsizei stride = VertexFloats * sizeof(float);
        gl->glEnableVertexAttribArray(0);
        gl->glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
        gl->glEnableVertexAttribArray(1);
        gl->glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                                  reinterpret_cast<const void*>(3 * sizeof(float)));
        gl->glEnableVertexAttribArray(2);
        gl->glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride,
                                  reinterpret_cast<const void*>(6 * sizeof(float)));
        gl->glBindVertexArray(0);
        meshIndexCount = GLsizei(data.indices.size());
        meshName = name;
    }

    /// Frees the GL objects and the context; afterwards the renderer holds nothing. At exit, a
    /// context that cannot be made current here (another thread's) is left to the process's end.
    void shutdown(bool atExit) {
        if (!parts.context) return;
        if (parts.context->makeCurrent(parts.surface.get())) {
            release();
            parts.context->doneCurrent();
        } else if (atExit) {
            (void)parts.context.release();
            (void)parts.surface.release();
        }
        parts.context.reset();
        parts.surface.reset();
        parts.gl = nullptr;
        gl = nullptr;
    }

    /// A vertex on the GPU: position, normal, texture coordinates.
    static constexpr int VertexFloats = 8;

    /// Pass 1 of a mesh render: the object's design-space positions and normals (and a flat
    /// design's texture coordinates) at n x n samples per output pixel, into `targets` (left
    /// bound as the framebuffer). Throws InputError for a flat design on a mesh without UVs.
    ObjectCamera drawGBuffer(const Genome& genome, const MeshSettings& settings, const glm::dvec3& cutNormal,
                             double cutOffset, GBufferTargets& targets);

    void release() {
        for (GlProgram& program : raster)
            program.release();
        if (opTexture) gl->glDeleteTextures(1, &opTexture);
        if (teethTexture) gl->glDeleteTextures(1, &teethTexture);
        if (teethBuffer) gl->glDeleteBuffers(1, &teethBuffer);
        if (pathsTexture) gl->glDeleteTextures(1, &pathsTexture);
        if (pathsBuffer) gl->glDeleteBuffers(1, &pathsBuffer);
        gbuffer.release();
        for (GlProgram& program : mesh)
            program.release();
        if (emptyVao) gl->glDeleteVertexArrays(1, &emptyVao);
        if (opBuffer) gl->glDeleteBuffers(1, &opBuffer);
        if (sourceTexture) gl->glDeleteTextures(1, &sourceTexture);
        if (meshVao) gl->glDeleteVertexArrays(1, &meshVao);
        if (meshVbo) gl->glDeleteBuffers(1, &meshVbo);
        if (meshIbo) gl->glDeleteBuffers(1, &meshIbo);
    }
};

bool GlRenderer::available(std::string* reason) {
    const GlProbe probe = probeGl();
    if (reason) *reason = probe.reason;
    return probe.available;
}

GlRenderer::GlRenderer()
    : mImpl(std::make_unique<Impl>()) {
    std::string why;
    if (!available(&why)) throw RuntimeFailure("OpenGL is not available: " + why);
    mImpl->parts = makeContext(why);
    if (!mImpl->parts.gl) throw RuntimeFailure("OpenGL is not available: " + why);
    mImpl->gl = mImpl->parts.gl;
    mImpl->gl->glGenVertexArrays(1, &mImpl->emptyVao);
    mImpl->gl->glGenBuffers(1, &mImpl->opBuffer);
    mImpl->gl->glGenTextures(1, &mImpl->opTexture);
    mImpl->gl->glGenBuffers(1, &mImpl->teethBuffer);
    mImpl->gl->glGenTextures(1, &mImpl->teethTexture);
    mImpl->gl->glGenBuffers(1, &mImpl->pathsBuffer);
    mImpl->gl->glGenTextures(1, &mImpl->pathsTexture);
    registerExitHandler();
    LiveRenderers& live = liveRenderers();
    std::lock_guard lock(live.mutex);
    Impl* impl = mImpl.get();
    live.teardown[impl] = [impl] { impl->shutdown(true); };
}

GlRenderer::~GlRenderer() {
    if (!mImpl) return;
    {
        LiveRenderers& live = liveRenderers();
        std::lock_guard lock(live.mutex);
        // Gone from the registry: the exit handler has torn this renderer down already.
        if (live.teardown.erase(mImpl.get()) == 0) return;
    }
    mImpl->shutdown(false);
}

std::string GlRenderer::rendererName() const {
    mImpl->makeCurrent();
    return reinterpret_cast<const char*>(mImpl->gl->glGetString(GL_RENDERER));
}

std::string GlRenderer::glVersion() const {
    auto [major, minor] = mImpl->parts.context->format().version();
    return std::to_string(major) + "." + std::to_string(minor);
}

void GlRenderer::checkProgram(const std::string& vertexSource, const std::string& fragmentSource) {
    mImpl->makeCurrent();
    auto load = [](const std::string& name) { return shaderFile(name); };
    GLuint program = buildProgram(*mImpl->gl, "checked program",
                                  {{GL_VERTEX_SHADER, expandIncludes(vertexSource, load)},
                                   {GL_FRAGMENT_SHADER, expandIncludes(fragmentSource, load)}});
    mImpl->gl->glDeleteProgram(program);
}

void GlRenderer::finish() {
    mImpl->makeCurrent();
    mImpl->gl->glFinish();
}

Image GlRenderer::render(const Genome& genome, const RenderSettings& settings) {
    checkRenderSettings(genome, settings);
    AaPattern aa = aaPattern(settings.aa);
    if (aa.offsets.size() > std::size_t(MaxSamples))
        throw InputError("antialiasing pattern " + aa.name + " has more samples than the GL back end takes");
    SampleFrame frame = sampleFrame(genome, settings);
    std::vector<PreparedOp> ops = prepare(genome);

    Impl& d = *mImpl;
    d.makeCurrent();
    auto* gl = d.gl;
    bool hasSource = genome.dimension == 2 && genome.source.has_value();
    const Features features = featuresOf(genome, ops);
    GlProgram& raster = d.buildRaster(genome.dimension, hasSource, features);
    gl->glUseProgram(raster.id());
    gl->glUniform1i(raster.uniform("uLoopProbe"), 2);

    std::vector<float> offsets, weights;
    for (std::size_t s = 0; s < aa.offsets.size(); ++s) {
        offsets.push_back(float(aa.offsets[s].x));
        offsets.push_back(float(aa.offsets[s].y));
        weights.push_back(float(aa.weights[s]));
    }
    gl->glUniform1i(raster.uniform("uSampleCount"), GLint(weights.size()));
    gl->glUniform2fv(raster.uniform("uOffsets"), GLsizei(weights.size()), offsets.data());
    gl->glUniform1fv(raster.uniform("uWeights"), GLsizei(weights.size()), weights.data());

    // Unit 2: units 0 and 1 get rebound by the targets and the mesh G-buffer.
    gl->glUniform1i(raster.uniform("uSource"), 2);
    if (hasSource) d.bindSource(genome);

    int side = std::min({MaxTileSide, d.limit(GL_MAX_RENDERBUFFER_SIZE), d.limit(GL_MAX_TEXTURE_SIZE)});
    GLint viewport[2] = {0, 0};
    gl->glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    side = std::min({side, int(viewport[0]), int(viewport[1])});
    double work = shaderWork(ops) * double(weights.size());
    int workSide = int(std::sqrt(MaxWorkPerDraw / work));
    side = std::max(64, std::min(side, workSide));
    int tileW = std::min(side, settings.width), tileH = std::min(side, settings.height);

    GLuint fbo = 0, texture = 0;
    d.makeTarget(tileW, tileH, fbo, texture);
    gl->glBindVertexArray(d.emptyVao);
    gl->glDisable(GL_DEPTH_TEST);
    gl->glDisable(GL_BLEND);

    Image image;
    image.width = settings.width;
    image.height = settings.height;
    image.rgb.resize(std::size_t(image.width) * std::size_t(image.height) * 3);
    std::vector<std::uint8_t> rgba(std::size_t(tileW) * std::size_t(tileH) * 4);
    try {
        for (int ty = 0; ty < settings.height; ty += tileH) {
            for (int tx = 0; tx < settings.width; tx += tileW) {
                int w = std::min(tileW, settings.width - tx), h = std::min(tileH, settings.height - ty);
                glm::dvec3 tileOrigin = frame.origin + double(tx) * frame.du + double(ty) * frame.dv;
                // The tile's centre as the reference: float positions are then small where the
                // samples are, however deep the region zooms.
                glm::dvec3 reference = tileOrigin + 0.5 * double(w) * frame.du + 0.5 * double(h) * frame.dv;
                if (genome.dimension == 2) reference.z = 0.0;
                d.uploadGenome(raster, ops, genome, reference);
                glm::vec3 origin(tileOrigin - reference), du(frame.du), dv(frame.dv);
                gl->glUniform3fv(raster.uniform("uOrigin"), 1, &origin.x);
                gl->glUniform3fv(raster.uniform("uDu"), 1, &du.x);
                gl->glUniform3fv(raster.uniform("uDv"), 1, &dv.x);
                gl->glViewport(0, 0, w, h);
                gl->glDrawArrays(GL_TRIANGLES, 0, 3);
                gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
                gl->glReadPixels(0, 0, w, h, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, rgba.data());
                d.checkErrors("the raster render");
                // Alpha 0 where the driver cut the stylus's loops short (tools.glsl,
                // loopsWereCut): those pixels are wrong, so the design is the CPU's to draw.
                if (features.stylus)
                    for (std::size_t i = 3; i < std::size_t(w) * std::size_t(h) * 4; i += 4)
                        if (rgba[i] == 0) {
                            const std::string name = rendererName();
                            throw RuntimeFailure("GL: " + name.substr(0, name.find(" (")) +
                                                 " stops a shader after so many loop iterations, too few for "
                                                 "this design's stylus strokes at these settings; the CPU "
                                                 "renderer draws it");
                        }
                for (int y = 0; y < h; ++y) {
                    const std::uint8_t* in = rgba.data() + std::size_t(y) * std::size_t(w) * 4;
                    std::uint8_t* out = image.row(ty + y) + std::size_t(tx) * 3;
                    for (int x = 0; x < w; ++x) {
                        out[x * 3 + 0] = in[x * 4 + 0];
                        out[x * 3 + 1] = in[x * 4 + 1];
                        out[x * 3 + 2] = in[x * 4 + 2];
                    }
                }
            }
        }
    } catch (...) {
        gl->glDeleteFramebuffers(1, &fbo);
        gl->glDeleteTextures(1, &texture);
        throw;
    }
    gl->glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl->glDeleteFramebuffers(1, &fbo);
    gl->glDeleteTextures(1, &texture);
    return image;
}

Image GlRenderer::renderMesh(const Genome& genome, const MeshSettings& settings) {
    glm::dvec3 cutNormal;
    double cutOffset = 0.0;
    checkMeshSettings(settings, cutNormal, cutOffset);
    const int n = settings.supersample;
    const bool flat = genome.dimension == 2;
    Impl& d = *mImpl;
    d.makeCurrent();
    auto* gl = d.gl;
    GBufferTargets targets(gl);
    GLuint outputFbo = 0, outputTexture = 0;
    auto cleanup = [&] {
        gl->glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (outputFbo) gl->glDeleteFramebuffers(1, &outputFbo);
        if (outputTexture) gl->glDeleteTextures(1, &outputTexture);
    };

    Image image;
    try {
        const ObjectCamera view = d.drawGBuffer(genome, settings, cutNormal, cutOffset, targets);

        // Pass 2: the colour rule per sample, lit and averaged.
        d.makeTarget(settings.width, settings.height, outputFbo, outputTexture);
        gl->glViewport(0, 0, settings.width, settings.height);
        std::vector<PreparedOp> ops = prepare(genome);
        const bool hasSource = flat && genome.source.has_value();
        GlProgram& mesh = d.buildShading(genome.dimension, hasSource, featuresOf(genome, ops));
        gl->glUseProgram(mesh.id());
        // A solid's operations relative to the box centre, where the G-buffer's points are; a
        // flat design's relative to its own centre, where the texture's middle lies.
        const FlatOnUvs flatOnUvs(genome);
        d.uploadGenome(mesh, ops, genome, flat ? glm::dvec3(0.5 * flatOnUvs.size, 0.0) : view.reference);
        if (hasSource) d.bindSource(genome);
        gl->glActiveTexture(GL_TEXTURE0);
        gl->glBindTexture(GL_TEXTURE_2D, targets.textures[0]);
        gl->glActiveTexture(GL_TEXTURE1);
        gl->glBindTexture(GL_TEXTURE_2D, targets.textures[1]);
        if (flat) {
            // Unit 6: 2 holds the source image, 3 to 5 the operations' buffers.
            gl->glActiveTexture(GL_TEXTURE6);
            gl->glBindTexture(GL_TEXTURE_2D, targets.textures[2]);
            gl->glUniform1i(mesh.uniform("uUvs"), 6);
            gl->glUniform1f(mesh.uniform("uFlatSide"), float(flatOnUvs.side));
            gl->glUniform2f(mesh.uniform("uFlatHalf"), float(0.5 * flatOnUvs.size.x),
                            float(0.5 * flatOnUvs.size.y));
        }
        gl->glActiveTexture(GL_TEXTURE0);
        gl->glUniform1i(mesh.uniform("uPositions"), 0);
        gl->glUniform1i(mesh.uniform("uNormals"), 1);
        gl->glUniform1i(mesh.uniform("uSource"), 2);
        gl->glUniform1i(mesh.uniform("uSupersample"), n);
        glm::vec3 eyeF(view.eye), light(view.light);
        gl->glUniform3fv(mesh.uniform("uEye"), 1, &eyeF.x);
        gl->glUniform3fv(mesh.uniform("uLight"), 1, &light.x);
        gl->glUniform1i(mesh.uniform("uLighting"), settings.lighting ? 1 : 0);
        glm::vec3 clear = linearColor(settings.clearColor);
        gl->glUniform3fv(mesh.uniform("uClear"), 1, &clear.x);
        gl->glBindVertexArray(d.emptyVao);
        gl->glDrawArrays(GL_TRIANGLES, 0, 3);

        std::vector<std::uint8_t> rgba(std::size_t(settings.width) * std::size_t(settings.height) * 4);
        gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
        gl->glReadPixels(0, 0, settings.width, settings.height, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE,
                         rgba.data());
        d.checkErrors("the shading pass");
        image.width = settings.width;
        image.height = settings.height;
        image.rgb.resize(std::size_t(image.width) * std::size_t(image.height) * 3);
        for (int y = 0; y < image.height; ++y) {
            // GL's first row is the bottom of the view.
            const std::uint8_t* in =
                rgba.data() + std::size_t(image.height - 1 - y) * std::size_t(image.width) * 4;
            std::uint8_t* out = image.row(y);
            for (int x = 0; x < image.width; ++x) {
                out[x * 3 + 0] = in[x * 4 + 0];
                out[x * 3 + 1] = in[x * 4 + 1];
                out[x * 3 + 2] = in[x * 4 + 2];
            }
        }
    } catch (...) {
        cleanup();
        throw;
    }
    cleanup();
    return image;
}

MeshGBuffer GlRenderer::renderMeshGBuffer(const Genome& genome, const MeshSettings& settings) {
    glm::dvec3 cutNormal;
    double cutOffset = 0.0;
    checkMeshSettings(settings, cutNormal, cutOffset);
    Impl& d = *mImpl;
    d.makeCurrent();
    auto* gl = d.gl;
    GBufferTargets targets(gl);
    const ObjectCamera view = d.drawGBuffer(genome, settings, cutNormal, cutOffset, targets);

    MeshGBuffer result;
    result.width = settings.width;
    result.height = settings.height;
    result.supersample = settings.supersample;
    result.reference = view.reference;
    result.eye = view.eye;
    result.light = view.light;
    const int gw = settings.width * settings.supersample, gh = settings.height * settings.supersample;
    const std::size_t floats = std::size_t(gw) * std::size_t(gh) * 4;
    result.positions.resize(floats);
    result.normals.resize(floats);
    gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    gl->glReadBuffer(GL_COLOR_ATTACHMENT0);
    gl->glReadPixels(0, 0, gw, gh, GL_RGBA, GL_FLOAT, result.positions.data());
    gl->glReadBuffer(GL_COLOR_ATTACHMENT1);
    gl->glReadPixels(0, 0, gw, gh, GL_RGBA, GL_FLOAT, result.normals.data());
    if (genome.dimension == 2) {
        result.uvs.resize(std::size_t(gw) * std::size_t(gh) * 2);
        gl->glReadBuffer(GL_COLOR_ATTACHMENT2);
        gl->glReadPixels(0, 0, gw, gh, GL_RG, GL_FLOAT, result.uvs.data());
    }
    gl->glReadBuffer(GL_COLOR_ATTACHMENT0);
    d.checkErrors("the G-buffer read-back");
    return result;
}

ObjectCamera GlRenderer::Impl::drawGBuffer(const Genome& genome, const MeshSettings& settings,
                                           const glm::dvec3& cutNormal, double cutOffset,
                                           GBufferTargets& targets) {
    Impl& d = *this;
    const int n = settings.supersample;
    d.buildMesh();
    d.loadMeshToGpu(settings.mesh);
    const bool flat = genome.dimension == 2;
    checkFlatDesignFits(genome, d.meshHasOwnUvs, settings.mesh);
    int gw = settings.width * n, gh = settings.height * n;
    if (gw > d.limit(GL_MAX_TEXTURE_SIZE) || gh > d.limit(GL_MAX_TEXTURE_SIZE))
        throw InputError("mesh render too large for this GPU at " + std::to_string(n) + "x" +
                         std::to_string(n) + " supersampling");

    const ObjectCamera view = frameObject(objectBox(genome), d.meshFit, settings);
    glm::mat4 viewProjection(view.viewProjection);
    const double scale = view.scale;

    const int targetCount = flat ? 3 : 2;
    gl->glGenTextures(targetCount, targets.textures);
    for (int k = 0; k < targetCount; ++k) {
        gl->glBindTexture(GL_TEXTURE_2D, targets.textures[k]);
        gl->glTexStorage2D(GL_TEXTURE_2D, 1, k == 2 ? GL_RG32F : GL_RGBA32F, gw, gh);
        gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    gl->glGenRenderbuffers(1, &targets.depth);
    gl->glBindRenderbuffer(GL_RENDERBUFFER, targets.depth);
    gl->glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, gw, gh);
    gl->glGenFramebuffers(1, &targets.fbo);
    gl->glBindFramebuffer(GL_FRAMEBUFFER, targets.fbo);
    gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, targets.textures[0], 0);
    gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, targets.textures[1], 0);
    if (flat)
        gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, targets.textures[2],
                                   0);
    gl->glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, targets.depth);
    d.checkFramebuffer("G-buffer");
    const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    gl->glDrawBuffers(targetCount, buffers);
    const float zero[4] = {0, 0, 0, 0};
    for (int k = 0; k < targetCount; ++k)
        gl->glClearBufferfv(GL_COLOR, k, zero);
    gl->glClear(GL_DEPTH_BUFFER_BIT);
    gl->glViewport(0, 0, gw, gh);
    gl->glEnable(GL_DEPTH_TEST);
    gl->glDepthFunc(GL_LESS);
    gl->glDisable(GL_CULL_FACE); // back faces carry the cut's cap and the inside of open meshes
    gl->glUseProgram(d.gbuffer.id());
    gl->glUniformMatrix4fv(d.gbuffer.uniform("uViewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
    glm::vec3 eyeF(view.eye), normalF(cutNormal);
    gl->glUniform3fv(d.gbuffer.uniform("uEye"), 1, &eyeF.x);
    gl->glUniform1i(d.gbuffer.uniform("uCut"), settings.cut ? 1 : 0);
    gl->glUniform3fv(d.gbuffer.uniform("uCutNormal"), 1, &normalF.x);
    gl->glUniform1f(d.gbuffer.uniform("uCutOffset"), float(cutOffset - glm::dot(cutNormal, view.reference)));
    gl->glUniform1f(d.gbuffer.uniform("uScale"), float(scale));
    gl->glBindVertexArray(d.meshVao);
    gl->glDrawElements(GL_TRIANGLES, d.meshIndexCount, GL_UNSIGNED_INT, nullptr);
    gl->glDisable(GL_DEPTH_TEST);
    d.checkErrors("the G-buffer pass");
    return view;
}

} // namespace marbler::gl
