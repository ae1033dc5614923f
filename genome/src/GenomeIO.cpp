#include "marbler/GenomeIO.h"

#include "marbler/Error.h"
#include "marbler/Params.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <system_error>

namespace marbler {
namespace {

using Json = nlohmann::ordered_json;

/// Deeper JSON than this is refused while parsing: nlohmann's dump and destructor paths
/// recurse, so hostile nesting must never reach them. A genome itself needs depth 4.
constexpr int MaxDepth = 64;

/// Below this sine of the angle between them, a 3D `direction` and `normal` count as parallel:
/// the part of `normal` across `direction` would be rounding noise.
constexpr double ParallelSine = 1e-9;

/// A vector this close to unit length (or a normal this close to orthogonal) is kept exactly as
/// written, so that normalising is idempotent and a saved file loads back bit for bit.
constexpr double UnitTolerance = 1e-14;

/// Thrown by the parser callback; turned into a GenomeError by parseGenome.
struct TooDeep {};

/// Shortest text that reads back as the same double ("-2", "0.1", "1e+300").
std::string formatNumber(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char text[64];
    auto [end, ec] = std::to_chars(text, text + sizeof text, value);
    return ec == std::errc() ? std::string(text, end) : std::to_string(value);
}

/// A JSON value shown in an error message: compact, one line, and short.
std::string describe(const Json& value) {
    std::string text;
    switch (value.type()) {
    case Json::value_t::object:
        return "an object";
    case Json::value_t::array:
        return "an array of " + std::to_string(value.size());
    case Json::value_t::null:
        return "null";
    case Json::value_t::number_float:
        return formatNumber(value.get<double>());
    default:
        text = value.dump(-1, ' ', true, Json::error_handler_t::replace);
    }
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return text;
}

std::string indexed(const std::string& where, std::size_t index) {
    return where + "[" + std::to_string(index) + "]";
}

std::string member(const std::string& where, std::string_view key) {
    return where.empty() ? std::string(key) : where + "." + std::string(key);
}

/// A number that keeps a file diff clean: integral values as JSON integers.
Json number(double value) {
    if (std::isfinite(value) && value == std::trunc(value) && std::abs(value) < 9.0e15)
        return static_cast<std::int64_t>(value);
    return value;
}

/// Unit vector of a non-zero finite vector; scaled first so that tiny or huge components
/// neither underflow nor overflow when squared.
glm::dvec3 unitVector(const glm::dvec3& v) {
    double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    glm::dvec3 scaled = v / largest;
    return scaled / glm::length(scaled);
}

bool isZero(const glm::dvec3& v) {
    return v.x == 0.0 && v.y == 0.0 && v.z == 0.0;
}

bool nearlyUnit(const glm::dvec3& v) {
    return std::abs(glm::dot(v, v) - 1.0) <= UnitTolerance;
}

/// Whether two non-zero vectors are parallel (or anti-parallel) to within ParallelSine.
bool parallel(const glm::dvec3& a, const glm::dvec3& b) {
    glm::dvec3 ua = unitVector(a), ub = unitVector(b);
    return glm::length(glm::cross(ua, ub)) <= ParallelSine;
}

const ParamSpec* findParam(std::span<const ParamSpec> params, ParamField field) {
    for (const ParamSpec& spec : params)
        if (spec.field == field) return &spec;
    return nullptr;
}

/// Walks a free-form value (meta), its recursion bounded by MaxDepth: refuses deeper nesting
/// and non-finite numbers, which JSON cannot write back.
void checkFreeForm(const Json& value, const std::string& where, const std::string& name, int depth) {
    if (depth > MaxDepth)
        throw GenomeError(name, where, "nested deeper than " + std::to_string(MaxDepth) + " levels");
    if (value.is_number_float() && !std::isfinite(value.get<double>()))
        throw GenomeError(name, where, "must be finite (got " + describe(value) + ")");
    if (value.is_object()) {
        for (auto it = value.begin(); it != value.end(); ++it)
            checkFreeForm(*it, member(where, it.key()), name, depth + 1);
    } else if (value.is_array()) {
        for (std::size_t i = 0; i < value.size(); ++i)
            checkFreeForm(value[i], indexed(where, i), name, depth + 1);
    }
}

// ---- Wrapping bath (docs/genome-format.md, "Wrapping bath") ----

} // namespace

/// The tools whose steps can lie in a bath that wraps (GenomeIO.h); whyCannotWrap says why not.
bool toolMayWrap(Tool tool) {
    switch (tool) {
    case Tool::Spray:
    case Tool::Stretch:
        return true;
    case Tool::Drop:
    case Tool::Cylinder:
    case Tool::Line:
    case Tool::Comb:
    case Tool::Wave:
    case Tool::Circle:
    case Tool::Sphere:
    case Tool::Vortex:
    case Tool::Flow:
    case Tool::Stylus:
        return false;
    }
    return false;
}

namespace {

/// Why one step cannot be taken modulo the design's lattice, or "" where it can: a spray (its
/// disc wraps, it moves nothing) and a stretch along an axis whose teeth span the period the
/// lattice gives across the pass (its shift is then a function of the position modulo that
/// period). Every other tool moves points by amounts that are not periodic in the design's size.
///
/// A stretch shifts along one axis by a function of the other coordinate, so it commutes with a
/// lattice vector (a, b) when that function's period divides the vector's component across the
/// pass. Straight: x-shifts need period h, y-shifts w. Half-drop ((w, h/2), (0, h)): an x-shift
/// by f(y) needs f(y + h/2) = f(y), so h/2; a y-shift by g(x) needs w. Brick ((w, 0), (w/2, h)):
/// an x-shift needs h; a y-shift needs w/2.
std::string whyCannotWrap(const Operation& op, const glm::dvec3& size, Lattice lattice, std::string& field) {
    field = "tool";
    const std::string tool(toolSpec(op.tool).name);
    if (op.tool == Tool::Drop)
        return "a drop pushes the inks by amounts that never fall to zero, so it cannot wrap; a bath that "
               "wraps takes spray (a drop that pushes nothing) instead";
    if (!toolMayWrap(op.tool))
        return "\"" + tool + "\" cannot wrap; a bath that wraps takes only spray and stretch along an axis";
    if (op.tool == Tool::Stretch) {
        field = "angle";
        if (std::fmod(op.angle, 90.0) != 0.0)
            return "a stretch in a bath that wraps must run along an axis: angle 0, 90, 180 or 270 (got " +
                   formatNumber(op.angle) + ")";
        field = "teeth";
        const bool alongX = std::fmod(std::abs(op.angle), 180.0) == 0.0; // N along y
        const bool halved = alongX ? lattice == Lattice::HalfDrop : lattice == Lattice::Brick;
        const double period = (alongX ? size.y : size.x) * (halved ? 0.5 : 1.0);
        const double span = op.teeth.empty() ? 0.0 : op.teeth.back() - op.teeth.front();
        if (!(std::abs(span - period) <= 1e-9 * period))
            return "a stretch in a bath that wraps must have teeth spanning " +
                   std::string(halved ? "half " : "") +
                   "the design across the pass, from the first tooth to the last " + formatNumber(period) +
                   " (" + (halved ? "half " : "") + "the design's " + (alongX ? "height" : "width") +
                   (halved ? std::string(", as a ") + (lattice == Lattice::HalfDrop ? "half-drop" : "brick") +
                                 " repeat needs"
                           : std::string()) +
                   "; got " + formatNumber(span) + ")";
    }
    return ""; // a spray: it moves nothing
}

/// A wrapping bath's rules: 2D, no source image, and every step one that commutes with the
/// wrap (whyCannotWrap).
void checkWraps(const Genome& genome, const std::string& name) {
    if (genome.dimension != 2) throw GenomeError(name, "wrap", "only 2D designs can wrap");
    // A spray's nearest image is found among three columns (half-drop) or rows (brick) of the
    // lattice, which is exact while the tile is at most 4 times as long across them.
    if (genome.lattice == Lattice::HalfDrop && genome.size.y > 4.0 * genome.size.x)
        throw GenomeError(name, "wrap",
                          "a half-drop repeat needs a design at most 4 times as tall as it is wide (got " +
                              formatNumber(genome.size.x) + " x " + formatNumber(genome.size.y) + ")");
    if (genome.lattice == Lattice::Brick && genome.size.x > 4.0 * genome.size.y)
        throw GenomeError(name, "wrap",
                          "a brick repeat needs a design at most 4 times as wide as it is tall (got " +
                              formatNumber(genome.size.x) + " x " + formatNumber(genome.size.y) + ")");
    if (genome.source)
        throw GenomeError(name, "wrap",
                          "a bath that wraps cannot have a source image (its edges would meet in a seam)");
    for (const auto& [list, key] :
         {std::pair{&genome.initial, "initial"}, std::pair{&genome.operations, "operations"}})
        for (std::size_t i = 0; i < list->size(); ++i) {
            std::string field;
            std::string why = whyCannotWrap((*list)[i], genome.size, genome.lattice, field);
            if (!why.empty()) throw GenomeError(name, member(indexed(key, i), field), why);
        }
}

// ---- end wrapping bath ----

/// The value rules of one entry (finite, positive, palette index, non-zero and non-parallel
/// directions). Shared by the loader and validateGenome so both say the same thing.
void checkOperation(const Operation& op, int dimension, int paletteSize, bool inInitial,
                    const std::string& where, const std::string& name) {
    if (static_cast<int>(op.tool) >= ToolCount)
        throw GenomeError(name, member(where, "tool"), "unknown tool");
    const ToolSpec& tool = toolSpec(op.tool);
    if (!tool.available(dimension))
        throw GenomeError(name, member(where, "tool"),
                          "\"" + std::string(tool.name) + "\" is not available in " +
                              std::to_string(dimension) + "D");
    if (inInitial && !allowedInInitial(op.tool, dimension))
        throw GenomeError(name, member(where, "tool"),
                          "\"" + std::string(tool.name) + "\" is not allowed in initial (only " +
                              initialToolsText() + ")");
    std::span<const ParamSpec> params = tool.params(dimension);
    for (const ParamSpec& spec : params) {
        std::string key = member(where, spec.key);
        if (spec.kind == ParamKind::Choice) {
            auto index = static_cast<std::size_t>(getComponent(spec, op, 0));
            if (index >= spec.choices.size()) throw GenomeError(name, key, spec.describeChoices());
            continue;
        }
        if (spec.kind == ParamKind::Teeth) {
            if (op.teeth.size() < 2 || op.teeth.size() > MaxTeeth)
                throw GenomeError(name, key,
                                  "must hold 2 to " + std::to_string(MaxTeeth) + " numbers (got " +
                                      std::to_string(op.teeth.size()) + ")");
            for (std::size_t i = 0; i < op.teeth.size(); ++i) {
                double value = op.teeth[i];
                if (!std::isfinite(value))
                    throw GenomeError(name, indexed(key, i),
                                      "must be finite (got " + formatNumber(value) + ")");
                if (i > 0 && !(value > op.teeth[i - 1]))
                    throw GenomeError(name, indexed(key, i),
                                      "must be greater than the tooth before it (" +
                                          formatNumber(op.teeth[i - 1]) + "; got " + formatNumber(value) +
                                          ")");
            }
            continue;
        }
        if (spec.kind == ParamKind::Path) {
            if (op.path.size() < 2 || op.path.size() > MaxPathPoints)
                throw GenomeError(name, key,
                                  "must hold 2 to " + std::to_string(MaxPathPoints) + " points (got " +
                                      std::to_string(op.path.size()) + ")");
            for (std::size_t i = 0; i < op.path.size(); ++i) {
                for (int j = 0; j < 2; ++j)
                    if (!std::isfinite(op.path[i][j]))
                        throw GenomeError(name, indexed(indexed(key, i), static_cast<std::size_t>(j)),
                                          "must be finite (got " + formatNumber(op.path[i][j]) + ")");
                if (i > 0 && op.path[i] == op.path[i - 1])
                    throw GenomeError(name, indexed(key, i), "must differ from the point before it");
            }
            continue;
        }
        if (spec.kind == ParamKind::Pressure) {
            if (!op.pressure.empty() && op.pressure.size() != op.path.size())
                throw GenomeError(name, key,
                                  "must hold one number per path point, " + std::to_string(op.path.size()) +
                                      " (got " + std::to_string(op.pressure.size()) + ")");
            for (std::size_t i = 0; i < op.pressure.size(); ++i) {
                double value = op.pressure[i];
                if (!std::isfinite(value))
                    throw GenomeError(name, indexed(key, i),
                                      "must be finite (got " + formatNumber(value) + ")");
                if (!spec.range.contains(value))
                    throw GenomeError(name, indexed(key, i),
                                      spec.range.describe() + " (got " + formatNumber(value) + ")");
            }
            continue;
        }
        if (spec.kind == ParamKind::Color) {
            if (op.color < 0 || op.color >= paletteSize)
                throw GenomeError(name, key,
                                  "must be an index into the palette, 0 to " +
                                      std::to_string(paletteSize - 1) + " (got " + std::to_string(op.color) +
                                      ")");
            continue;
        }
        int count = componentCount(spec, op, dimension);
        bool many = spec.kind == ParamKind::Position || spec.kind == ParamKind::Direction ||
                    spec.kind == ParamKind::Extent || (spec.pair && count == 2);
        for (int i = 0; i < count; ++i) {
            double value = getComponent(spec, op, i);
            std::string at = many ? indexed(key, static_cast<std::size_t>(i)) : key;
            if (!std::isfinite(value))
                throw GenomeError(name, at, "must be finite (got " + formatNumber(value) + ")");
            if (!spec.range.contains(value))
                throw GenomeError(name, at, spec.range.describe() + " (got " + formatNumber(value) + ")");
        }
        if (spec.kind == ParamKind::Direction) {
            glm::dvec3 v(getComponent(spec, op, 0), getComponent(spec, op, 1), getComponent(spec, op, 2));
            if (isZero(v)) throw GenomeError(name, key, "must be non-zero");
        }
    }
    if (dimension == 3 && findParam(params, ParamField::Direction) && findParam(params, ParamField::Normal) &&
        parallel(op.direction, op.normal))
        throw GenomeError(name, member(where, "normal"), "must not be parallel to direction");
    if (op.tool == Tool::Stylus && op.steps < minimumStylusSteps(op)) {
        int needed = minimumStylusSteps(op);
        throw GenomeError(
            name, member(where, "steps"),
            needed > MaxStylusSteps
                ? "cannot be enough: this path, alpha, lambda, reach, tines and pressure need "
                  "more than " +
                      std::to_string(MaxStylusSteps) + " steps (got " + std::to_string(op.steps) +
                      "); split the stroke into "
                      "shorter strokes"
                : "must be at least max(4 L / reach, 2 L k c_max (3.1 / reach + 0.65 / lambda + "
                  "6.3 lambda / reach^2)) = " +
                      std::to_string(needed) + " (got " + std::to_string(op.steps) + ")");
    }
    if (op.tool == Tool::Flow && op.steps < minimumFlowSteps(op)) {
        int needed = minimumFlowSteps(op);
        throw GenomeError(
            name, member(where, "steps"),
            needed > MaxFlowSteps
                ? "cannot be enough: this speed, time and size need more than " +
                      std::to_string(MaxFlowSteps) + " steps (got " + std::to_string(op.steps) + ")"
                : "must be at least 32 |speed| time max(size) / min(size)^2 = " + std::to_string(needed) +
                      " (got " + std::to_string(op.steps) + ")");
    }
}

/// Normalises `direction`, `axis` and `normal` (the latter made orthogonal to `direction`),
/// leaving vectors that already are unit (and orthogonal) untouched so that a second load
/// changes nothing.
void normalise(Operation& op, int dimension) {
    if (dimension != 3) return;
    std::span<const ParamSpec> params = toolSpec(op.tool).params(dimension);
    if (findParam(params, ParamField::Axis) && !nearlyUnit(op.axis)) op.axis = unitVector(op.axis);
    if (!findParam(params, ParamField::Direction)) return;
    if (!nearlyUnit(op.direction)) op.direction = unitVector(op.direction);
    if (!findParam(params, ParamField::Normal)) return;
    if (nearlyUnit(op.normal) && std::abs(glm::dot(op.normal, op.direction)) <= UnitTolerance) return;
    // Gram-Schmidt twice: once leaves a residue of rounding error over the sine of the angle
    // between the two, which a nearly parallel pair turns into a visibly skewed normal.
    glm::dvec3 n = unitVector(op.normal);
    for (int pass = 0; pass < 2; ++pass)
        n = unitVector(n - glm::dot(n, op.direction) * op.direction);
    op.normal = n;
}

/// Reads a JSON genome into a Genome, checking types and shapes; the value rules follow in
/// validateGenome.
class Reader {
public:
    Reader(const std::string& name, std::vector<std::string>* warnings)
        : mName(name)
        , mWarnings(warnings) {}

    Genome read(const Json& root) {
        if (!root.is_object()) fail("", "must be a JSON object (got " + describe(root) + ")");
        Genome genome;
        readHeader(root, genome);
        readColors(root, genome);

        const Json& initial = require(root, "", "initial");
        const Json& operations = require(root, "", "operations");
        if (!initial.is_array()) fail("initial", "must be an array (got " + describe(initial) + ")");
        if (!operations.is_array()) fail("operations", "must be an array (got " + describe(operations) + ")");
        if (initial.size() + operations.size() > MaxEntries)
            fail("operations", "too many entries: at most " + std::to_string(MaxEntries) +
                                   " in initial and operations together (got " +
                                   std::to_string(initial.size() + operations.size()) + ")");
        genome.initial.reserve(initial.size());
        for (std::size_t i = 0; i < initial.size(); ++i)
            genome.initial.push_back(readOperation(initial[i], indexed("initial", i), genome.dimension,
                                                   genome.palette.size(), true));
        genome.operations.reserve(operations.size());
        for (std::size_t i = 0; i < operations.size(); ++i)
            genome.operations.push_back(readOperation(operations[i], indexed("operations", i),
                                                      genome.dimension, genome.palette.size(), false));

        if (auto it = root.find("source"); it != root.end())
            genome.source = readSource(*it, genome.dimension);
        if (auto it = root.find("bleed"); it != root.end()) {
            needVersion2("bleed");
            genome.bleed = readNumber(*it, "bleed");
        }
        // ---- Wrapping bath (docs/genome-format.md, "Wrapping bath") ----
        if (auto it = root.find("wrap"); it != root.end()) {
            needVersion(3, "wrap");
            if (it->is_boolean()) {
                genome.wrap = it->get<bool>();
            } else if (auto lattice =
                           it->is_string() ? latticeFromName(it->get<std::string>()) : std::nullopt) {
                genome.wrap = true;
                genome.lattice = *lattice;
            } else {
                fail("wrap", "must be true, false, \"straight\", \"half-drop\" or \"brick\" (got " +
                                 describe(*it) + ")");
            }
        }
        // ---- end wrapping bath ----
        if (auto it = root.find("meta"); it != root.end()) {
            if (!it->is_object()) fail("meta", "must be an object (got " + describe(*it) + ")");
            genome.meta = Meta::fromJson(*it);
        }
        static constexpr std::array Known{"format",     "version", "dimension", "size",
                                          "background", "palette", "initial",   "operations",
                                          "source",     "bleed",   "wrap",      "meta"};
        for (auto it = root.begin(); it != root.end(); ++it)
            if (std::find(Known.begin(), Known.end(), it.key()) == Known.end()) warnUnknown("", it.key());
        return genome;
    }

private:
    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw GenomeError(mName, where, what);
    }

    /// A version-2 feature in a file that says version 1 is refused, so that an older reader
    /// (which would ignore it) and a newer one never disagree about one file.
    void needVersion2(const std::string& where, const std::string& what = "") const {
        needVersion(2, where, what);
    }

    void needVersion(int version, const std::string& where, const std::string& what = "") const {
        if (mVersion >= version) return;
        fail(where, (what.empty() ? std::string() : what + " ") + "needs format version " +
                        std::to_string(version) + " (the file says version " + std::to_string(mVersion) +
                        ")");
    }

    void warnUnknown(const std::string& where, const std::string& key) {
        if (!mWarnings) return;
        std::string clean;
        for (char ch : key)
            clean += static_cast<unsigned char>(ch) < 0x20 ? '?' : ch;
        mWarnings->push_back(mName + ": " + (where.empty() ? "" : where + ": ") + "unknown key \"" + clean +
                             "\" ignored");
    }

    const Json& require(const Json& object, const std::string& where, std::string_view key) const {
        auto it = object.find(key);
        if (it == object.end()) fail(member(where, key), "missing");
        return *it;
    }

    /// An integral number (2 and 2.0 alike), for version, dimension and colour indices.
    static bool integral(const Json& value) {
        if (value.is_number_integer()) return true;
        if (!value.is_number_float()) return false;
        double v = value.get<double>();
        return std::isfinite(v) && v == std::trunc(v);
    }

    double readNumber(const Json& value, const std::string& where) const {
        if (!value.is_number()) fail(where, "must be a number (got " + describe(value) + ")");
        return value.get<double>();
    }

    void readHeader(const Json& root, Genome& genome) {
        const Json& format = require(root, "", "format");
        if (format != "marbler-genome")
            fail("format", "must be \"marbler-genome\" (got " + describe(format) + ")");

        const Json& version = require(root, "", "version");
        if (!integral(version)) fail("version", "must be an integer (got " + describe(version) + ")");
        double v = version.get<double>();
        if (v > FormatVersion)
            fail("version", "made by a newer version of Marbler (format version " + describe(version) +
                                "; this one reads version " + std::to_string(FormatVersion) + ")");
        if (v < 1)
            fail("version",
                 "must be 1 or " + std::to_string(FormatVersion) + " (got " + describe(version) + ")");
        mVersion = static_cast<int>(v);

        const Json& dimension = require(root, "", "dimension");
        if (!integral(dimension) || (dimension.get<double>() != 2.0 && dimension.get<double>() != 3.0))
            fail("dimension", "must be 2 or 3 (got " + describe(dimension) + ")");
        genome.dimension = static_cast<int>(dimension.get<double>());

        const Json& size = require(root, "", "size");
        if (!size.is_array() || size.size() != static_cast<std::size_t>(genome.dimension))
            fail("size", "must be an array of " + std::to_string(genome.dimension) + " numbers (got " +
                             describe(size) + ")");
        for (int i = 0; i < genome.dimension; ++i)
            genome.size[i] =
                readNumber(size[static_cast<std::size_t>(i)], indexed("size", static_cast<std::size_t>(i)));
    }

    Color readColor(const Json& value, const std::string& where) const {
        std::optional<Color> color;
        if (value.is_string()) color = parseHexColor(value.get<std::string>());
        if (!color) fail(where, "must be a colour \"#rrggbb\" (got " + describe(value) + ")");
        return *color;
    }

    void readColors(const Json& root, Genome& genome) {
        genome.background = readColor(require(root, "", "background"), "background");
        const Json& palette = require(root, "", "palette");
        if (!palette.is_array() || palette.empty() || palette.size() > MaxPaletteSize)
            fail("palette", "must be an array of 1 to " + std::to_string(MaxPaletteSize) + " colours (got " +
                                describe(palette) + ")");
        for (std::size_t i = 0; i < palette.size(); ++i)
            genome.palette.push_back(readColor(palette[i], indexed("palette", i)));
    }

    /// Reads `count` numbers: an array when `asArray`, else one number.
    void readComponents(const Json& value, const std::string& where, const ParamSpec& spec, Operation& op,
                        int count, bool asArray) const {
        if (!asArray) {
            setComponent(spec, op, 0, readNumber(value, where));
            return;
        }
        if (!value.is_array() || value.size() != static_cast<std::size_t>(count))
            fail(where,
                 "must be an array of " + std::to_string(count) + " numbers (got " + describe(value) + ")");
        for (int i = 0; i < count; ++i)
            setComponent(
                spec, op, i,
                readNumber(value[static_cast<std::size_t>(i)], indexed(where, static_cast<std::size_t>(i))));
    }

    Operation readOperation(const Json& entry, const std::string& where, int dimension,
                            std::size_t paletteSize, bool inInitial) {
        if (!entry.is_object()) fail(where, "must be an object (got " + describe(entry) + ")");
        const Json& toolName = require(entry, where, "tool");
        if (!toolName.is_string())
            fail(member(where, "tool"), "must be a tool name (got " + describe(toolName) + ")");
        const ToolSpec* tool = findTool(toolName.get<std::string>());
        if (!tool) fail(member(where, "tool"), "unknown tool " + describe(toolName));
        if (!tool->available(dimension))
            fail(member(where, "tool"), describe(toolName) + " is not available in " +
                                            std::to_string(dimension) + "D (" + (tool->in3D ? "3D" : "2D") +
                                            " only)");
        if (inInitial && !allowedInInitial(tool->tool, dimension))
            fail(member(where, "tool"),
                 describe(toolName) + " is not allowed in initial (only " + initialToolsText() + ")");

        if (tool->version >= 2) needVersion(tool->version, member(where, "tool"), describe(toolName));
        Operation op;
        op.tool = tool->tool;
        std::span<const ParamSpec> params = tool->params(dimension);
        // Choices (a wave's shape) decide how many numbers the wave's pairs hold, so they are
        // read first.
        for (const ParamSpec& spec : params) {
            if (spec.kind != ParamKind::Choice) continue;
            const Json& value = require(entry, where, spec.key);
            int index = value.is_string() ? spec.choiceIndex(value.get<std::string>()) : -1;
            if (index < 0)
                fail(member(where, spec.key), spec.describeChoices() + " (got " + describe(value) + ")");
            setComponent(spec, op, 0, index);
        }
        for (const ParamSpec& spec : params) {
            if (spec.kind == ParamKind::Choice) continue;
            std::string at = member(where, spec.key);
            if (spec.optional && !entry.contains(spec.key)) {
                // Left out: the table's default (a list, a stylus's pressure, stays empty: all 1).
                if (spec.kind != ParamKind::Pressure && componentCount(spec, op, dimension) == 1)
                    setComponent(spec, op, 0, spec.defaultValue);
                continue;
            }
            if (spec.version >= 2) needVersion(spec.version, at);
            const Json& value = require(entry, where, spec.key);
            int count = componentCount(spec, op, dimension);
            switch (spec.kind) {
            case ParamKind::Teeth: {
                if (!value.is_array() || value.size() < 2 || value.size() > MaxTeeth)
                    fail(at, "must be an array of 2 to " + std::to_string(MaxTeeth) + " numbers (got " +
                                 describe(value) + ")");
                for (std::size_t i = 0; i < value.size(); ++i)
                    setComponent(spec, op, static_cast<int>(i), readNumber(value[i], indexed(at, i)));
                break;
            }
            case ParamKind::Count: {
                if (!integral(value)) fail(at, "must be an integer (got " + describe(value) + ")");
                double n = value.get<double>();
                if (!spec.range.contains(n))
                    fail(at, spec.range.describe() + " (got " + describe(value) + ")");
                setComponent(spec, op, 0, n);
                break;
            }
            case ParamKind::Extent:
                readComponents(value, at, spec, op, count, true);
                break;
            case ParamKind::Path: {
                if (!value.is_array() || value.size() < 2 || value.size() > MaxPathPoints)
                    fail(at, "must be an array of 2 to " + std::to_string(MaxPathPoints) +
                                 " points [x, y] (got " + describe(value) + ")");
                for (std::size_t i = 0; i < value.size(); ++i) {
                    std::string point = indexed(at, i);
                    if (!value[i].is_array() || value[i].size() != 2)
                        fail(point, "must be a point [x, y] (got " + describe(value[i]) + ")");
                    for (std::size_t j = 0; j < 2; ++j)
                        setComponent(spec, op, static_cast<int>(2 * i + j),
                                     readNumber(value[i][j], indexed(point, j)));
                }
                break;
            }
            case ParamKind::Pressure: {
                if (!value.is_array() || value.size() != op.path.size())
                    fail(at, "must be an array of one number per path point, " +
                                 std::to_string(op.path.size()) + " (got " + describe(value) + ")");
                for (std::size_t i = 0; i < value.size(); ++i)
                    setComponent(spec, op, static_cast<int>(i), readNumber(value[i], indexed(at, i)));
                break;
            }
            case ParamKind::Position:
            case ParamKind::Direction:
                readComponents(value, at, spec, op, count, true);
                break;
            case ParamKind::Color: {
                if (!integral(value))
                    fail(at, "must be an integer palette index (got " + describe(value) + ")");
                // Range-checked here, before the cast to int could overflow.
                double index = value.get<double>();
                if (index < 0 || index >= static_cast<double>(paletteSize))
                    fail(at, "must be an index into the palette, 0 to " + std::to_string(paletteSize - 1) +
                                 " (got " + describe(value) + ")");
                op.color = static_cast<int>(index);
                break;
            }
            default:
                readComponents(value, at, spec, op, count, spec.pair && count == 2);
                break;
            }
        }
        if (op.tool == Tool::Stylus && op.tines > 1 && !entry.contains("spacing"))
            fail(member(where, "spacing"), "missing: a rake (tines > 1) needs the spacing of its tines");
        for (auto it = entry.begin(); it != entry.end(); ++it) {
            if (it.key() == "tool") continue;
            bool known = std::any_of(params.begin(), params.end(),
                                     [&](const ParamSpec& s) { return s.key == it.key(); });
            if (!known) warnUnknown(where, it.key());
        }
        return op;
    }

    SourceImage readSource(const Json& value, int dimension) {
        if (dimension != 2) fail("source", "only allowed in 2D designs");
        if (!value.is_object())
            fail("source", "must be an object {\"image\": ...} (got " + describe(value) + ")");
        const Json& image = require(value, "source", "image");
        if (!image.is_string() || image.get<std::string>().empty())
            fail("source.image", "must be a file name or a data URL (got " + describe(image) + ")");
        for (auto it = value.begin(); it != value.end(); ++it)
            if (it.key() != "image") warnUnknown("source", it.key());
        return SourceImage{image.get<std::string>()};
    }

    std::string mName;
    std::vector<std::string>* mWarnings;
    int mVersion = FormatVersion; ///< the version the file says
};

/// "line L, column C" of a byte offset (0-based) of the text.
std::string textPosition(std::string_view text, std::size_t offset) {
    offset = std::min(offset, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

/// nlohmann's explanation without its "[json.exception...] ... column N: " prefix, on one line:
/// no control characters or stray bytes from the input reach stderr.
std::string explanation(const std::string& message) {
    std::string what = message;
    if (auto at = what.find("column "); at != std::string::npos) {
        if (auto colon = what.find(": ", at); colon != std::string::npos) what = what.substr(colon + 2);
    } else if (auto bracket = what.find("] "); bracket != std::string::npos) {
        what = what.substr(bracket + 2);
    }
    for (char& ch : what)
        if (static_cast<unsigned char>(ch) < 0x20 || static_cast<unsigned char>(ch) >= 0x7f) ch = '?';
    return what;
}

/// A JSON syntax error, located by nlohmann's byte count (1-based: the last byte read).
[[noreturn]] void syntaxError(std::string_view text, const nlohmann::json::parse_error& e,
                              const std::string& name) {
    throw GenomeError(name, textPosition(text, e.byte == 0 ? 0 : e.byte - 1),
                      "JSON " + explanation(e.what()));
}

/// Any other failure of the JSON reader; a number too large for a double names itself in the
/// message ("number overflow parsing '1e999'"), which locates it in the text.
[[noreturn]] void readerError(std::string_view text, const nlohmann::json::exception& e,
                              const std::string& name) {
    std::string what = explanation(e.what());
    std::string location;
    auto open = what.find('\''), close = what.rfind('\'');
    if (open != std::string::npos && close > open + 1) {
        std::string token = what.substr(open + 1, close - open - 1);
        if (auto at = text.find(token); at != std::string_view::npos) location = textPosition(text, at);
    }
    throw GenomeError(name, location, "JSON " + what);
}

Json operationJson(const Operation& op, int dimension) {
    Json entry = Json::object();
    entry["tool"] = std::string(toolSpec(op.tool).name);
    for (const ParamSpec& spec : toolSpec(op.tool).params(dimension)) {
        std::string key(spec.key);
        int count = componentCount(spec, op, dimension);
        if (spec.kind == ParamKind::Choice) {
            entry[key] = std::string(spec.choices[static_cast<std::size_t>(getComponent(spec, op, 0))]);
        } else if (spec.kind == ParamKind::Color) {
            entry[key] = op.color;
        } else if (spec.optional && !usesVersion2(spec, op)) {
            continue; // at its default: left out, so the file stays the lowest version
        } else if (spec.kind == ParamKind::Count) {
            entry[key] = static_cast<int>(getComponent(spec, op, 0));
        } else if (spec.kind == ParamKind::Path) {
            Json points = Json::array();
            for (const glm::dvec2& p : op.path)
                points.push_back(Json::array({number(p.x), number(p.y)}));
            entry[key] = std::move(points);
        } else if (spec.kind == ParamKind::Position || spec.kind == ParamKind::Direction ||
                   spec.kind == ParamKind::Extent || spec.kind == ParamKind::Teeth ||
                   spec.kind == ParamKind::Pressure || (spec.pair && count == 2)) {
            Json values = Json::array();
            for (int i = 0; i < count; ++i)
                values.push_back(number(getComponent(spec, op, i)));
            entry[key] = std::move(values);
        } else {
            entry[key] = number(getComponent(spec, op, 0));
        }
    }
    return entry;
}

} // namespace

Genome parseGenome(std::string_view text, const std::string& name, std::vector<std::string>* warnings) {
    if (text.size() > MaxFileBytes)
        throw GenomeError(name, "",
                          "larger than " + std::to_string(MaxFileBytes / (1024 * 1024)) + " MiB (" +
                              std::to_string(text.size()) + " bytes)");
    Json root;
    try {
        Json::parser_callback_t refuseDeep = [](int depth, Json::parse_event_t event, Json&) {
            if ((event == Json::parse_event_t::object_start || event == Json::parse_event_t::array_start) &&
                depth >= MaxDepth)
                throw TooDeep{};
            return true;
        };
        root = Json::parse(text.begin(), text.end(), refuseDeep);
    } catch (const TooDeep&) {
        throw GenomeError(name, "", "JSON nested deeper than " + std::to_string(MaxDepth) + " levels");
    } catch (const nlohmann::json::parse_error& e) {
        syntaxError(text, e, name);
    } catch (const nlohmann::json::exception& e) {
        readerError(text, e, name);
    }
    Genome genome = Reader(name, warnings).read(root);
    validateGenome(genome, name);
    for (Operation& op : genome.initial)
        normalise(op, genome.dimension);
    for (Operation& op : genome.operations)
        normalise(op, genome.dimension);
    return genome;
}

Genome loadGenome(const std::filesystem::path& file, std::vector<std::string>* warnings) {
    const std::string name = file.string();
    std::error_code ec;
    std::filesystem::file_status status = std::filesystem::status(file, ec);
    if (ec) throw GenomeError(name, "", "cannot read: " + ec.message());
    if (!std::filesystem::exists(status)) throw GenomeError(name, "", "cannot read: no such file");
    if (std::filesystem::is_directory(status)) throw GenomeError(name, "", "cannot read: is a folder");
    // The size is checked before reading so a huge file is never pulled into memory; the read
    // below is bounded too, in case the file grows meanwhile or is not a regular file.
    std::uintmax_t bytes = std::filesystem::file_size(file, ec);
    if (!ec && bytes > MaxFileBytes)
        throw GenomeError(name, "",
                          "larger than " + std::to_string(MaxFileBytes / (1024 * 1024)) + " MiB (" +
                              std::to_string(bytes) + " bytes)");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw GenomeError(name, "", std::string("cannot read: ") + std::strerror(errno));
    std::string text;
    text.resize(MaxFileBytes + 1);
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (in.bad()) throw GenomeError(name, "", "cannot read: I/O error");
    text.resize(static_cast<std::size_t>(in.gcount()));
    Genome genome = parseGenome(text, name, warnings);
    std::filesystem::path folder = file.parent_path();
    genome.baseDirectory = folder.empty() ? std::string(".") : folder.string();
    genome.fileName = name;
    return genome;
}

void validateGenome(const Genome& genome, const std::string& name) {
    if (genome.dimension != 2 && genome.dimension != 3)
        throw GenomeError(name, "dimension", "must be 2 or 3 (got " + std::to_string(genome.dimension) + ")");
    for (int i = 0; i < genome.dimension; ++i) {
        double side = genome.size[i];
        std::string at = indexed("size", static_cast<std::size_t>(i));
        if (!std::isfinite(side))
            throw GenomeError(name, at, "must be finite (got " + formatNumber(side) + ")");
        if (!(side > 0.0)) throw GenomeError(name, at, "must be > 0 (got " + formatNumber(side) + ")");
    }
    if (genome.palette.empty() || genome.palette.size() > MaxPaletteSize)
        throw GenomeError(name, "palette",
                          "must hold 1 to " + std::to_string(MaxPaletteSize) + " colours (got " +
                              std::to_string(genome.palette.size()) + ")");
    if (genome.initial.size() + genome.operations.size() > MaxEntries)
        throw GenomeError(name, "operations",
                          "too many entries: at most " + std::to_string(MaxEntries) +
                              " in initial and operations together (got " +
                              std::to_string(genome.initial.size() + genome.operations.size()) + ")");
    int paletteSize = static_cast<int>(genome.palette.size());
    for (std::size_t i = 0; i < genome.initial.size(); ++i)
        checkOperation(genome.initial[i], genome.dimension, paletteSize, true, indexed("initial", i), name);
    for (std::size_t i = 0; i < genome.operations.size(); ++i)
        checkOperation(genome.operations[i], genome.dimension, paletteSize, false, indexed("operations", i),
                       name);
    if (genome.source) {
        if (genome.dimension != 2) throw GenomeError(name, "source", "only allowed in 2D designs");
        if (genome.source->image.empty())
            throw GenomeError(name, "source.image", "must be a file name or a data URL");
    }
    if (!std::isfinite(genome.bleed))
        throw GenomeError(name, "bleed", "must be finite (got " + formatNumber(genome.bleed) + ")");
    if (!(genome.bleed >= 0.0))
        throw GenomeError(name, "bleed", "must be >= 0 (got " + formatNumber(genome.bleed) + ")");
    if (genome.wrap) checkWraps(genome, name);
    checkFreeForm(genome.meta.toJson(), "meta", name, 1);
}

std::string_view latticeName(Lattice lattice) {
    switch (lattice) {
    case Lattice::Straight:
        return "straight";
    case Lattice::HalfDrop:
        return "half-drop";
    case Lattice::Brick:
        return "brick";
    }
    return "straight";
}

std::optional<Lattice> latticeFromName(std::string_view name) {
    for (Lattice lattice : {Lattice::Straight, Lattice::HalfDrop, Lattice::Brick})
        if (latticeName(lattice) == name) return lattice;
    return std::nullopt;
}

bool canWrap(const Genome& genome) {
    return wrapProblem(genome).empty();
}

std::string wrapProblem(const Genome& genome) {
    // The loader's own rule and words, without the file's name in front.
    const std::string name = "design";
    try {
        checkWraps(genome, name);
    } catch (const GenomeError& e) {
        return std::string(e.what()).substr(name.size() + 2);
    }
    return {};
}

Json toJson(const Genome& genome) {
    Json root = Json::object();
    root["format"] = "marbler-genome";
    root["version"] = requiredVersion(genome);
    root["dimension"] = genome.dimension;
    Json size = Json::array();
    for (int i = 0; i < (genome.dimension == 3 ? 3 : 2); ++i)
        size.push_back(number(genome.size[i]));
    root["size"] = std::move(size);
    root["background"] = toHex(genome.background);
    Json palette = Json::array();
    for (const Color& color : genome.palette)
        palette.push_back(toHex(color));
    root["palette"] = std::move(palette);
    Json initial = Json::array();
    for (const Operation& op : genome.initial)
        initial.push_back(operationJson(op, genome.dimension));
    root["initial"] = std::move(initial);
    Json operations = Json::array();
    for (const Operation& op : genome.operations)
        operations.push_back(operationJson(op, genome.dimension));
    root["operations"] = std::move(operations);
    if (genome.source) root["source"] = Json{{"image", genome.source->image}};
    if (genome.bleed != 0.0) root["bleed"] = number(genome.bleed);
    if (genome.wrap && genome.lattice == Lattice::Straight) root["wrap"] = true;
    if (genome.wrap && genome.lattice != Lattice::Straight)
        root["wrap"] = std::string(latticeName(genome.lattice));
    if (!genome.meta.empty()) root["meta"] = genome.meta.toJson();
    return root;
}

std::string serializeGenome(const Genome& genome) {
    // `replace` rather than throwing: a string built in memory with broken UTF-8 (a meta note)
    // should not make a design unsaveable.
    return toJson(genome).dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

void saveGenome(const Genome& genome, const std::filesystem::path& file) {
    writeFileAtomically(file, serializeGenome(genome));
}

} // namespace marbler
