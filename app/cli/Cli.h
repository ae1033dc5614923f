#pragma once
/// The headless `marbler` verbs (spec/cli.md). Each verb parses its own arguments and returns
/// the process exit status: 0 success, 2 bad usage or bad input (one line on stderr naming the
/// file and what is wrong), 1 any other failure.

#include "marbler/Genome.h"
#include "marbler/Mesh.h"

#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace marbler::cli {

/// Exit statuses of the command line.
inline constexpr int ExitOk = 0;
inline constexpr int ExitFailure = 1;
inline constexpr int ExitBadInput = 2;

/// Parsed arguments: positional words and `--name value` / `--name=value` / `--flag` options.
struct Args {
    std::vector<std::string> positional;
    std::map<std::string, std::string> options;

    bool has(const std::string& name) const { return options.count(name) != 0; }
    std::optional<std::string> get(const std::string& name) const;
};

/// The flags every verb takes besides its own (issue 29: `paper --quiet` was refused while
/// `render --quiet` was not): -h/--help, --quiet (no progress line) and --progress (a progress
/// line even when stderr is no terminal). A verb with no progress to show accepts the last two
/// and does nothing with them, so one script's options fit every verb.
inline const std::vector<std::string> CommonFlags = {"h", "help", "quiet", "progress"};

/// Parses `words` (after the verb). `valued` lists options that take a value, `flags` those
/// that do not (both without the leading dashes; `-o` is spelled "o"); CommonFlags are always
/// accepted. Throws InputError for an unknown option or a missing value.
Args parseArgs(std::span<const std::string> words, const std::vector<std::string>& valued,
               const std::vector<std::string>& flags);

/// The one GENOME argument of `marbler VERB GENOME ...`; InputError when there is none or more.
const std::string& oneGenomeArgument(const Args& args, const std::string& verb);
/// The value of `-o`/`--output`; InputError "-o WHAT is required (see marbler VERB --help)" when
/// it is absent or empty.
std::string requiredOutput(const Args& args, const std::string& verb, const std::string& what = "OUT");

/// Number parsing for options; throw InputError naming the option.
int parseIntOption(const Args& args, const std::string& name, int fallback, int lo, int hi);
double parseDoubleOption(const Args& args, const std::string& name, double fallback);
std::uint64_t parseSeedOption(const Args& args, const std::string& name);
/// `--dpi`: a positive number up to 1e6, or `fallback` when the option is absent.
double parseDpiOption(const Args& args, double fallback);
/// `count` numbers separated by commas, the value of `--option`.
std::vector<double> parseNumberList(const std::string& option, const std::string& text, std::size_t count);
/// A print size `--size WIDTHxHEIGHT{cm,mm,in}`, in inches.
std::pair<double, double> parsePrintSize(const std::string& text);
/// Pixels from a length in pixels, refusing what cannot be an image before any allocation;
/// `what` names the length in the message.
int pixelsOf(double value, const std::string& what);

/// One line of progress on stderr, rewritten in place only when its text changes and cleared by
/// finish() (or when it goes). It shows when stderr is a terminal or `--progress` is given, never
/// with `--quiet`. show() may be called from the renderer's worker threads.
class ProgressLine {
public:
    explicit ProgressLine(const Args& args);
    ~ProgressLine() { finish(); }
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    void show(const std::string& text);
    void finish();

private:
    const bool mEnabled;
    std::mutex mMutex;
    std::string mText; ///< on the line now; empty when nothing is
};

/// Loads the GENOME argument of a verb: a genome file, or a PNG or TIFF image that carries one
/// (marbler::loadDesign; the one place the verbs read genomes). Warnings go to stderr as
/// "marbler VERB: warning: ...". Throws GenomeError or InputError naming the file.
Genome loadGenomeArgument(const char* verb, const std::string& file);

/// `--mesh NAME|FILE`: a built-in object, or a mesh file read by assimp in the window module
/// (the executable links no assimp, so only a mesh file pays for loading it). Throws InputError
/// when it is neither or the file cannot be read.
MeshData meshOf(const std::string& nameOrFile);

/// The verbs. `words` are the arguments after the verb.
int runRender(std::span<const std::string> words);
int runInfo(std::span<const std::string> words);
int runRandom(std::span<const std::string> words);
int runBreed(std::span<const std::string> words);
int runDoctor(std::span<const std::string> words);
int runSvg(std::span<const std::string> words);
int runBake(std::span<const std::string> words);
int runAnimate(std::span<const std::string> words);
int runVideo(std::span<const std::string> words);
int runPaper(std::span<const std::string> words);

/// Runs `body`, turning a marbler::InputError into one stderr line and exit 2, and any other
/// exception into one line and exit 1.
int guarded(const char* verb, const std::function<int()>& body);

} // namespace marbler::cli
