// The making of a design rendered: the growth rule against the independent renders of
// growth-v2.json, `marbler render --steps K` and `marbler animate` through the executable.

#include "RenderTestUtil.h"
#include "TestUtil.h"
#include "marbler/CpuRenderer.h"
#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"
#include "marbler/Growth.h"
#include "marbler/Video.h"

#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <numbers>

#include <sys/wait.h>
#include <unistd.h>

namespace marbler {
namespace {

using test::runMarbler;

/// The conformance genome saved as a file for the executable.
std::filesystem::path growthGenomeFile(const std::filesystem::path& dir) {
    const Genome genome = test::genomeOf(test::loadConformance("growth-v2.json"), "growth-v2.json");
    const auto file = dir / "growth.marble.json";
    saveGenome(genome, file);
    return file;
}

RenderSettings tiny() {
    RenderSettings settings;
    settings.width = settings.height = 24;
    settings.aa = "none";
    return settings;
}

/// Holds a 24x24 render without antialiasing to an independent one: every pixel exact (a pixel
/// is one sample, so it shows a palette colour or the background), except where the pixel's
/// centre lies a hair (0.05 design units; a pixel is 41.7) from an ink boundary, where two
/// implementations in double precision may see either side: there the colour expected must
/// be seen within that distance. Returns the number of such pixels.
int expectMatches(const Genome& design, const nlohmann::json& rows, const std::string& what) {
    CpuRenderer renderer(design);
    const RenderSettings settings = tiny();
    const Image image = renderer.render(settings);
    const SampleFrame frame = sampleFrame(design, settings);
    int atEdges = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) {
            const std::uint8_t* got = image.row(y) + x * 3;
            const Color want{rows[y][x][0].get<std::uint8_t>(), rows[y][x][1].get<std::uint8_t>(),
                             rows[y][x][2].get<std::uint8_t>()};
            if (Color{got[0], got[1], got[2]} == want) continue;
            const glm::dvec3 p = frame.at(x, y, 0.0, 0.0);
            bool seenNearby = false;
            for (int k = 0; k < 32 && !seenNearby; ++k) {
                const double a = 2.0 * std::numbers::pi * k / 32;
                const int index = renderer.colorIndexAt(p + 0.05 * glm::dvec3(std::cos(a), std::sin(a), 0.0));
                seenNearby = (index >= 0 ? design.palette[index] : design.background) == want;
            }
            EXPECT_TRUE(seenNearby) << what << " pixel (" << x << ", " << y << "): got " << int(got[0]) << " "
                                    << int(got[1]) << " " << int(got[2]) << ", expected "
                                    << rows[y][x].dump();
            ++atEdges;
        }
    EXPECT_LE(atEdges, 2) << what;
    return atEdges;
}

TEST(GrowthConformance, FramesAndStepsMatchTheIndependentRenders) {
    const nlohmann::json file = test::loadConformance("growth-v2.json");
    const Genome genome = test::genomeOf(file, "growth-v2.json");
    const nlohmann::json& frames = file.at("frames");
    ASSERT_EQ(frames.size(), 9u);
    int atEdges = 0;
    for (int f = 0; f < 9; ++f)
        atEdges += expectMatches(designAtGrowth(genome, frameGrowth(stepCount(genome), f, 9)), frames[f],
                                 "frame " + std::to_string(f));
    int steps = 0;
    for (const auto& [k, rows] : file.at("steps").items()) {
        atEdges += expectMatches(designAfterSteps(genome, std::stoul(k)), rows, "steps " + k);
        ++steps;
    }
    EXPECT_EQ(steps, 4);
    std::printf("pixels a hair from an edge: %d of %d\n", atEdges, (9 + steps) * 24 * 24);
}

/// An image equal to the in-process render of `design` at 24x24.
void expectRenderOf(const Image& image, const Genome& design, const std::string& what) {
    const Image want = CpuRenderer(design).render(tiny());
    ASSERT_EQ(image.width, 24) << what;
    ASSERT_EQ(image.height, 24) << what;
    EXPECT_EQ(image.rgb, want.rgb) << what;
}

TEST(Animate, FramesFollowTheGrowthRuleAndCarryTheirOwnDesign) {
    const auto dir = test::outputDir("animate-frames");
    const auto genomeFile = growthGenomeFile(dir);
    const Genome genome = loadGenome(genomeFile);
    const auto out = dir / "frames";
    auto r = runMarbler({"animate", genomeFile.string(), "-o", out.string(), "--frames", "9", "--width", "24",
                         "--height", "24"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << "no progress when stderr is not a terminal: " << r.err;
    int count = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(out))
        ++count;
    EXPECT_EQ(count, 9);
    for (int f = 0; f < 9; ++f) {
        char name[32];
        std::snprintf(name, sizeof name, "frame-%04d.png", f);
        const Genome design = designAtGrowth(genome, frameGrowth(stepCount(genome), f, 9));
        expectRenderOf(test::readImage8(out / name), design, name);
        // The frame reloads as the partial design it shows.
        EXPECT_EQ(loadDesign(out / name), design) << name;
    }
    // The first frame is the bare bath.
    const Image first = test::readImage8(out / "frame-0000.png");
    for (std::size_t i = 0; i < first.rgb.size(); i += 3)
        ASSERT_EQ((Color{first.rgb[i], first.rgb[i + 1], first.rgb[i + 2]}), genome.background);
    // The last equals `render` at the same size.
    r = runMarbler({"render", genomeFile.string(), "-o", (dir / "whole.png").string(), "--width", "24"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(test::readImage8(out / "frame-0008.png").rgb, test::readImage8(dir / "whole.png").rgb);
    // Nothing else beside OUT (no temporary left).
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        names.insert(entry.path().filename().string());
    EXPECT_EQ(names, (std::set<std::string>{"frames", "growth.marble.json", "whole.png"}));
}

TEST(Animate, DefaultsAndSizes) {
    const auto dir = test::outputDir("animate-defaults");
    const auto genomeFile = growthGenomeFile(dir);
    // 4 seconds at 2 frames a second; the height keeps the design's aspect.
    auto r = runMarbler({"animate", genomeFile.string(), "-o", (dir / "a").string(), "--fps", "2", "--width",
                         "10", "--aa", "rgss"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "a" / "frame-0007.png"));
    EXPECT_FALSE(std::filesystem::exists(dir / "a" / "frame-0008.png"));
    EXPECT_EQ(test::readImage8(dir / "a" / "frame-0003.png").height, 10);
    // An empty folder may stand at OUT.
    std::filesystem::create_directory(dir / "b");
    r = runMarbler(
        {"animate", genomeFile.string(), "-o", (dir / "b").string(), "--frames", "2", "--height", "6"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(test::readImage8(dir / "b" / "frame-0001.png").width, 6);
}

/// A failure: exit 2, one stderr line that mentions `mention`, and nothing new in `dir`.
void expectBadUsage(const std::vector<std::string>& args, const std::string& mention,
                    const std::filesystem::path& dir) {
    std::set<std::filesystem::path> before;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        before.insert(entry.path());
    auto r = runMarbler(args);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(test::lineCount(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        EXPECT_TRUE(before.count(entry.path())) << "left behind: " << entry.path();
}

TEST(Animate, BadUsageExitsTwoWithOneLineAndNoOutput) {
    const auto dir = test::outputDir("animate-bad");
    const std::string genome = growthGenomeFile(dir).string();
    const std::string out = (dir / "out").string();
    expectBadUsage({"animate", genome, "-o", out, "--frames", "1"}, "--frames", dir);
    expectBadUsage({"animate", genome, "-o", out, "--frames", "ten"}, "--frames", dir);
    expectBadUsage({"animate", genome, "-o", out, "--frames", "-4"}, "--frames", dir);
    expectBadUsage({"animate", genome, "-o", out, "--fps", "0"}, "--fps", dir);
    expectBadUsage({"animate", genome, "-o", out, "--width", "0"}, "--width", dir);
    expectBadUsage({"animate", genome, "-o", out, "--aa", "grid99"}, "grid99", dir);
    expectBadUsage({"animate", genome, "-o", out, "--slice", "z=5"}, "--slice", dir);
    expectBadUsage({"animate", genome, "-o", out, "--bogus"}, "--bogus", dir);
    expectBadUsage({"animate", genome}, "-o OUT", dir);
    expectBadUsage({"animate", (dir / "missing.marble.json").string(), "-o", out}, "missing.marble.json",
                   dir);
    expectBadUsage({"animate", genome, "-o", genome}, "already exists", dir);
}

/// Starts `marbler animate` to `out` (many large frames, so it is still rendering when
/// interrupted), waits until something of its output exists in `dir`, interrupts it with SIGINT
/// and expects exit status 130 and nothing left but the genome.
void expectInterruptLeavesNothing(const std::filesystem::path& dir, const std::filesystem::path& genomeFile,
                                  const std::filesystem::path& out) {
    pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        std::freopen("/dev/null", "w", stderr);
        ::execl(MARBLER_EXECUTABLE, "marbler", "animate", genomeFile.c_str(), "-o", out.c_str(), "--frames",
                "5000", "--width", "400", "--quiet", static_cast<char*>(nullptr));
        ::_exit(127);
    }
    // Wait (without a time limit of our own: ctest's applies) for the temporary folder's second
    // frame, or the video's temporary file.
    bool started = false;
    while (!started) {
        for (const auto& entry : std::filesystem::directory_iterator(dir)) {
            const std::string name = entry.path().filename().string();
            if (entry.is_directory() ? std::filesystem::exists(entry.path() / "frame-0001.png")
                                     : name.find(".part-") != std::string::npos)
                started = true;
        }
        if (started) break;
        int early = 0;
        ASSERT_EQ(::waitpid(pid, &early, WNOHANG), 0) << "marbler animate ended before its first frames";
        ::usleep(20000);
    }
    ::kill(pid, SIGINT);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 130);
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        names.insert(entry.path().filename().string());
    EXPECT_EQ(names, std::set<std::string>{"growth.marble.json"}) << out;
}

TEST(Animate, InterruptLeavesNothingBehind) {
    const auto dir = test::outputDir("animate-interrupt");
    const auto genomeFile = growthGenomeFile(dir);
    expectInterruptLeavesNothing(dir, genomeFile, dir / "frames");
    expectInterruptLeavesNothing(dir, genomeFile, dir / "growth.mp4");
}

/// The mean absolute channel difference of two RGB buffers of equal size.
double meanDifference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        sum += std::abs(int(a[i]) - int(b[i]));
    return sum / double(a.size());
}

class AnimateVideo : public ::testing::TestWithParam<std::string> {};

TEST_P(AnimateVideo, HoldsEveryFrameAtTheRateFromBathToDesign) {
    const std::string extension = GetParam();
    const auto dir = test::outputDir("animate-video" + extension);
    const auto genomeFile = growthGenomeFile(dir);
    const Genome genome = loadGenome(genomeFile);
    const auto out = dir / ("growth" + extension);
    auto r = runMarbler({"animate", genomeFile.string(), "-o", out.string(), "--frames", "6", "--fps", "10",
                         "--width", "128"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<std::vector<std::uint8_t>> want;
    RenderSettings settings;
    settings.width = settings.height = 128;
    for (int f = 0; f < 6; ++f)
        want.push_back(
            CpuRenderer(designAtGrowth(genome, frameGrowth(stepCount(genome), f, 6))).render(settings).rgb);

    if (extension == ".webp") {
        // FFmpeg reads no animated WebP: count its frames (ANMF chunks) in the RIFF container.
        const std::string bytes = test::readFile(out);
        ASSERT_GT(bytes.size(), 12u);
        ASSERT_EQ(bytes.substr(0, 4), "RIFF");
        ASSERT_EQ(bytes.substr(8, 4), "WEBP");
        int frames = 0;
        for (std::size_t at = 12; at + 8 <= bytes.size();) {
            const auto byte = [&](std::size_t i) { return std::uint32_t(std::uint8_t(bytes[at + 4 + i])); };
            const std::uint32_t size = byte(0) | byte(1) << 8 | byte(2) << 16 | byte(3) << 24;
            if (bytes.compare(at, 4, "ANMF") == 0) ++frames;
            at += 8 + size + (size & 1);
        }
        EXPECT_EQ(frames, 6);
        return;
    }
    auto reader = openVideoReader(out);
    EXPECT_EQ(reader->width(), 128);
    EXPECT_EQ(reader->height(), 128);
    EXPECT_NEAR(reader->fps(), 10.0, 1e-9);
    std::vector<std::vector<std::uint8_t>> frames;
    std::vector<std::uint8_t> rgb;
    while (reader->nextFrame(rgb))
        frames.push_back(rgb);
    ASSERT_EQ(frames.size(), 6u);
    // A GIF holds the design's few colours exactly. H.264 and VP9 blur the sharp ink edges and
    // halve the colour resolution (4:2:0): measured, the whole design differs by a mean 13-14
    // levels at 128 x 128 (the flat bath by 0.3). So each frame must be nearest its own render
    // of all six (the growth shows, in order), the bath close, the design within a loose bound.
    const double bound = extension == ".gif" ? 1.0 : 20.0;
    for (std::size_t f = 0; f < 6; ++f) {
        const double own = meanDifference(frames[f], want[f]);
        EXPECT_LT(own, f == 0 ? std::min(bound, 2.0) : bound) << "frame " << f;
        for (std::size_t other = 0; other < 6; ++other)
            if (other != f) {
                EXPECT_LT(own, meanDifference(frames[f], want[other])) << "frame " << f << " vs " << other;
            }
    }
}

INSTANTIATE_TEST_SUITE_P(Formats, AnimateVideo, ::testing::Values(".mp4", ".webm", ".gif", ".webp"),
                         [](const auto& info) { return info.param.substr(1); });

TEST(Animate, BadVideoUsageLeavesNothing) {
    const auto dir = test::outputDir("animate-video-bad");
    const std::string genome = growthGenomeFile(dir).string();
    std::filesystem::create_directory(dir / "folder.mp4");
    expectBadUsage({"animate", genome, "-o", (dir / "folder.mp4").string(), "--frames", "2"},
                   "already exists", dir);
    expectBadUsage({"animate", genome, "-o", (dir / "huge.webm").string(), "--frames", "2", "--width",
                    "20000", "--height", "8"},
                   "huge.webm", dir);
}

TEST(Animate, HelpDescribesEveryOption) {
    auto r = runMarbler({"animate", "--help"});
    EXPECT_EQ(r.exitCode, 0);
    for (const char* option :
         {"-o", "--frames", "--fps", "--width", "--height", "--aa", "--slice", "--threads", "--quiet",
          "--progress", "frame-0000.png", ".gif", ".webp", ".mp4", ".webm", "partial design"})
        EXPECT_NE(r.out.find(option), std::string::npos) << option;
    EXPECT_NE(runMarbler({"--help"}).out.find("animate"), std::string::npos);
}

TEST(RenderSteps, StepsMatchTheGrowthRuleAndTheImageCarriesThem) {
    const auto dir = test::outputDir("render-steps");
    const auto genomeFile = growthGenomeFile(dir);
    const Genome genome = loadGenome(genomeFile);
    for (std::size_t k : {std::size_t(0), std::size_t(1), std::size_t(60), stepCount(genome)}) {
        const auto out = dir / ("steps-" + std::to_string(k) + ".png");
        auto r = runMarbler({"render", genomeFile.string(), "-o", out.string(), "--width", "24", "--steps",
                             std::to_string(k)});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        expectRenderOf(test::readImage8(out), designAfterSteps(genome, k), out.filename().string());
        EXPECT_EQ(loadDesign(out), designAfterSteps(genome, k)) << k;
    }
    EXPECT_NE(runMarbler({"render", "--help"}).out.find("--steps K"), std::string::npos);
}

TEST(RenderSteps, BadStepsExitTwoWithOneLineAndNoOutput) {
    const auto dir = test::outputDir("render-steps-bad");
    const std::string genome = growthGenomeFile(dir).string();
    const std::string out = (dir / "out.png").string();
    const std::string tooMany = std::to_string(stepCount(loadGenome(genome)) + 1);
    expectBadUsage({"render", genome, "-o", out, "--steps", tooMany}, "--steps", dir);
    expectBadUsage({"render", genome, "-o", out, "--steps", "-1"}, "--steps", dir);
    expectBadUsage({"render", genome, "-o", out, "--steps", "1.5"}, "--steps", dir);
    expectBadUsage({"render", genome, "-o", out, "--steps", "many"}, "--steps", dir);
    expectBadUsage({"render", genome, "-o", out, "--steps", "99999999999999"}, "--steps", dir);
    expectBadUsage({"render", genome, "-o", out, "--steps"}, "--steps", dir);
}

} // namespace
} // namespace marbler
