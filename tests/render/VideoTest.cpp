// Video files (marbler/Video.h): a short synthetic animation written in every format this
// machine's FFmpeg encodes and read back (animated WebP, which FFmpeg 5 cannot decode, by
// libwebp's own decoder), the exact frame rate, and nothing left behind on failure.

#include "marbler/Video.h"
#include "TestUtil.h"
#include "marbler/Error.h"

#include <gtest/gtest.h>

extern "C" {
#include <libavformat/avformat.h>
}

#include <webp/demux.h>

#include <array>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace marbler {
namespace {

namespace fs = std::filesystem;

constexpr int Width = 64, Height = 48, Frames = 6;
using Rgb = std::array<int, 3>;

/// Frame k: its left half one colour, its right half another, every colour distinct.
Rgb leftColour(int k) {
    static const Rgb colours[Frames] = {{220, 30, 40},  {30, 200, 60},  {40, 60, 210},
                                        {230, 210, 40}, {200, 40, 200}, {250, 250, 250}};
    return colours[k];
}
Rgb rightColour(int k) {
    static const Rgb colours[Frames] = {{20, 20, 20},  {120, 120, 120}, {40, 200, 210},
                                        {160, 90, 30}, {90, 30, 120},   {60, 140, 90}};
    return colours[k];
}

std::vector<std::uint8_t> frame(int k, int width = Width, int height = Height) {
    std::vector<std::uint8_t> rgb(std::size_t(width) * std::size_t(height) * 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            Rgb c = x < width / 2 ? leftColour(k) : rightColour(k);
            for (int i = 0; i < 3; ++i)
                rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3 + std::size_t(i)] =
                    std::uint8_t(c[i]);
        }
    return rgb;
}

void writeFrames(const fs::path& file, double fps, int width = Width, int height = Height) {
    auto writer = openVideoWriter(file, width, height, fps);
    for (int k = 0; k < Frames; ++k) {
        std::vector<std::uint8_t> rgb = frame(k, width, height);
        writer->addFrame(rgb.data(), std::size_t(width) * 3);
    }
    EXPECT_FALSE(fs::exists(file)) << "the file exists before finish()";
    writer->finish();
}

/// The colour at (x, y) of a packed RGB frame of `width` pixels a row.
Rgb pixel(const std::vector<std::uint8_t>& rgb, int width, int x, int y) {
    const std::size_t at = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
    return {rgb[at], rgb[at + 1], rgb[at + 2]};
}

void expectNear(const Rgb& got, const Rgb& want, int tolerance, const std::string& where) {
    for (int i = 0; i < 3; ++i)
        EXPECT_LE(std::abs(got[std::size_t(i)] - want[std::size_t(i)]), tolerance)
            << where << " channel " << i << ": got " << got[std::size_t(i)] << ", want "
            << want[std::size_t(i)];
}

/// Checks the middle of each half of each frame (away from the edge between them, which chroma
/// subsampling and dithering blur).
void expectFrameColours(int k, const std::vector<std::uint8_t>& rgb, int width, int tolerance,
                        const std::string& what) {
    for (int y : {8, 24, 40}) {
        expectNear(pixel(rgb, width, 12, y), leftColour(k), tolerance,
                   what + " frame " + std::to_string(k) + " left");
        expectNear(pixel(rgb, width, 52, y), rightColour(k), tolerance,
                   what + " frame " + std::to_string(k) + " right");
    }
}

class VideoRoundTrip : public ::testing::TestWithParam<const char*> {};

TEST_P(VideoRoundTrip, FramesSizeRateAndColoursSurvive) {
    const std::string extension = GetParam();
    const fs::path dir = test::outputDir(std::string("video-") + (extension.c_str() + 1));
    const fs::path file = dir / ("six" + extension);
    writeFrames(file, 25.0);
    ASSERT_TRUE(fs::exists(file));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1)
        << "a temporary file is left";

    auto reader = openVideoReader(file);
    EXPECT_EQ(reader->width(), Width);
    EXPECT_EQ(reader->height(), Height);
    EXPECT_NEAR(reader->fps(), 25.0, 1e-9);
    std::vector<std::uint8_t> rgb;
    int count = 0;
    // Lossy codecs move a flat colour by a few levels; the GIF palette holds these 12 exactly.
    const int tolerance = extension == ".gif" ? 2 : 10;
    while (reader->nextFrame(rgb)) {
        ASSERT_EQ(rgb.size(), std::size_t(Width) * Height * 3);
        if (count < Frames) expectFrameColours(count, rgb, Width, tolerance, extension);
        ++count;
    }
    EXPECT_EQ(count, Frames);
}

INSTANTIATE_TEST_SUITE_P(Formats, VideoRoundTrip, ::testing::Values(".mp4", ".webm", ".gif"),
                         [](const auto& info) { return std::string(info.param + 1); });

TEST(Video, AnimatedWebpHoldsEveryFrame) {
    const fs::path dir = test::outputDir("video-webp");
    const fs::path file = dir / "six.webp";
    writeFrames(file, 25.0);
    const std::string bytes = test::readFile(file);
    ASSERT_GT(bytes.size(), 12u);
    EXPECT_EQ(bytes.substr(0, 4), "RIFF");
    EXPECT_EQ(bytes.substr(8, 4), "WEBP");

    WebPData data{reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()};
    WebPAnimDecoderOptions options;
    ASSERT_TRUE(WebPAnimDecoderOptionsInit(&options));
    options.color_mode = MODE_RGBA;
    std::unique_ptr<WebPAnimDecoder, void (*)(WebPAnimDecoder*)> decoder(WebPAnimDecoderNew(&data, &options),
                                                                         WebPAnimDecoderDelete);
    ASSERT_TRUE(decoder);
    WebPAnimInfo info;
    ASSERT_TRUE(WebPAnimDecoderGetInfo(decoder.get(), &info));
    EXPECT_EQ(info.canvas_width, std::uint32_t(Width));
    EXPECT_EQ(info.canvas_height, std::uint32_t(Height));
    EXPECT_EQ(info.frame_count, std::uint32_t(Frames));
    int count = 0, previous = 0;
    while (WebPAnimDecoderHasMoreFrames(decoder.get())) {
        std::uint8_t* rgba = nullptr;
        int timestamp = 0;
        ASSERT_TRUE(WebPAnimDecoderGetNext(decoder.get(), &rgba, &timestamp));
        // Each frame shows for 40 ms at 25 frames a second.
        EXPECT_EQ(timestamp - previous, 40) << "frame " << count;
        previous = timestamp;
        std::vector<std::uint8_t> rgb;
        for (int p = 0; p < Width * Height; ++p)
            rgb.insert(rgb.end(), rgba + p * 4, rgba + p * 4 + 3);
        if (count < Frames) expectFrameColours(count, rgb, Width, 10, ".webp");
        ++count;
    }
    EXPECT_EQ(count, Frames);
}

TEST(Video, FrameRateIsKeptExactly) {
    // 30000/1001 (NTSC), not 29.97 rounded.
    const double ntsc = 30000.0 / 1001.0;
    for (const char* name : {"ntsc.mp4", "ntsc.webm"}) {
        const fs::path file = test::outputDir(std::string("video-rate-") + name) / name;
        writeFrames(file, ntsc);
        EXPECT_NEAR(openVideoReader(file)->fps(), ntsc, 1e-9) << name;
    }
}

/// The delays of a GIF's frames in hundredths of a second, from its graphic control extensions
/// (0x21 0xf9 0x04, flags, the delay in two bytes little-endian).
std::vector<int> gifDelays(const std::string& bytes) {
    std::vector<int> delays;
    for (std::size_t at = bytes.find("\x21\xf9\x04", 0, 3); at != std::string::npos && at + 6 <= bytes.size();
         at = bytes.find("\x21\xf9\x04", at + 3, 3))
        delays.push_back(std::uint8_t(bytes[at + 4]) | std::uint8_t(bytes[at + 5]) << 8);
    return delays;
}

TEST(Video, GifKeepsACoarseRateOnAverage) {
    // GIF counts hundredths of a second: 12 frames a second is 8 1/3 hundredths a frame, written
    // 8, 9, 8, 8, 9, 8 (50 hundredths for 6 frames, half a second), not 8 each (12.5 a second).
    const fs::path file = test::outputDir("video-rate-gif") / "twelve.gif";
    writeFrames(file, 12.0);
    const std::vector<int> delays = gifDelays(test::readFile(file));
    ASSERT_EQ(delays.size(), std::size_t(Frames));
    int total = 0;
    for (int delay : delays) {
        EXPECT_TRUE(delay == 8 || delay == 9) << delay;
        total += delay;
    }
    EXPECT_EQ(total, 50);
}

TEST(Video, OddSizesAreWritten) {
    // H.264 needs even sides in 4:2:0: an odd side is one pixel larger, its last row repeated.
    const fs::path dir = test::outputDir("video-odd");
    writeFrames(dir / "odd.webm", 25.0, 63, 47);
    auto vp9 = openVideoReader(dir / "odd.webm");
    EXPECT_EQ(vp9->width(), 63);
    EXPECT_EQ(vp9->height(), 47);
    writeFrames(dir / "odd.mp4", 25.0, 63, 47);
    auto h264 = openVideoReader(dir / "odd.mp4");
    EXPECT_EQ(h264->width(), 64);
    EXPECT_EQ(h264->height(), 48);
    std::vector<std::uint8_t> rgb;
    ASSERT_TRUE(h264->nextFrame(rgb));
    expectNear(pixel(rgb, 64, 63, 47), rightColour(0), 10, "the repeated corner");
}

TEST(Video, UnfinishedOrFailedWritesLeaveNothing) {
    const fs::path dir = test::outputDir("video-unfinished");
    {
        auto writer = openVideoWriter(dir / "gone.mp4", Width, Height, 25.0);
        std::vector<std::uint8_t> rgb = frame(0);
        writer->addFrame(rgb.data(), Width * 3);
    }
    EXPECT_TRUE(fs::is_empty(dir));
    EXPECT_THROW(openVideoWriter(dir / "a.avi", Width, Height, 25.0), InputError);
    EXPECT_THROW(openVideoWriter(dir / "a.gif", 0, Height, 25.0), InputError);
    EXPECT_THROW(openVideoWriter(dir / "a.gif", Width, Height, 0.0), InputError);
    EXPECT_THROW(openVideoWriter(dir / "no-such-folder" / "a.mp4", Width, Height, 25.0), RuntimeFailure);
    EXPECT_TRUE(fs::is_empty(dir));
}

TEST(Video, FormatsAreToldByExtension) {
    for (const char* name : {"a.gif", "a.WEBP", "b.mp4", "c.Webm"})
        EXPECT_TRUE(isVideoFile(name)) << name;
    for (const char* name : {"a.png", "a.avi", "mp4", "a.mp4.json"})
        EXPECT_FALSE(isVideoFile(name)) << name;
}

TEST(Video, ReadingWhatIsNoVideoIsBadInput) {
    const fs::path dir = test::outputDir("video-bad-input");
    EXPECT_THROW(openVideoReader(dir / "missing.mp4"), InputError);
    test::writeFile(dir / "text.mp4", "this is not a video, only a few words of text\n");
    EXPECT_THROW(openVideoReader(dir / "text.mp4"), InputError);
}

/// Muxes `frames` frames of raw 8 x 8 RGB video into a QuickTime file with libavformat: an
/// allowed container holding a codec that is not allowed.
void writeRawQuickTime(const fs::path& file, int frames) {
    AVFormatContext* out = nullptr;
    ASSERT_GE(avformat_alloc_output_context2(&out, nullptr, "mov", file.c_str()), 0);
    AVStream* stream = avformat_new_stream(out, nullptr);
    ASSERT_TRUE(stream);
    stream->time_base = AVRational{1, 25};
    stream->codecpar->codec_type = AVMEDIA_TYPE_VIDEO;
    stream->codecpar->codec_id = AV_CODEC_ID_RAWVIDEO;
    stream->codecpar->width = 8;
    stream->codecpar->height = 8;
    stream->codecpar->format = AV_PIX_FMT_RGB24;
    ASSERT_GE(avio_open(&out->pb, file.c_str(), AVIO_FLAG_WRITE), 0);
    ASSERT_GE(avformat_write_header(out, nullptr), 0);
    for (int f = 0; f < frames; ++f) {
        AVPacket* packet = av_packet_alloc();
        ASSERT_GE(av_new_packet(packet, 8 * 8 * 3), 0);
        std::memset(packet->data, 40 + 60 * f, std::size_t(packet->size));
        packet->pts = packet->dts = av_rescale_q(f, AVRational{1, 25}, stream->time_base);
        packet->flags |= AV_PKT_FLAG_KEY;
        ASSERT_GE(av_interleaved_write_frame(out, packet), 0);
        av_packet_free(&packet);
    }
    av_write_trailer(out);
    avio_closep(&out->pb);
    avformat_free_context(out);
}

TEST(Video, OnlyCommonCodecsReachADecoder) {
    const fs::path file = test::outputDir("video-codec-allow-list") / "raw.mov";
    writeRawQuickTime(file, 3);
    try {
        openVideoReader(file);
        ADD_FAILURE() << "raw video was read";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("its video is raw video: videos must be H.264, H.265, VP8, VP9, AV1"),
                  std::string::npos)
            << what;
    }
}

TEST(Video, OnlyCommonContainersReachADecoder) {
    // A YUV4MPEG stream is a few lines of text and raw pixels that FFmpeg reads as it reads any
    // of its dozens of formats; renamed .mp4, it was decoded before the allow-list.
    const fs::path dir = test::outputDir("video-allow-list");
    std::string y4m = "YUV4MPEG2 W8 H8 F25:1 Ip A1:1 C420jpeg\n";
    for (int frame = 0; frame < 3; ++frame)
        y4m += "FRAME\n" + std::string(8 * 8 * 3 / 2, char(40 + 60 * frame));
    for (const char* name : {"stream.y4m", "disguised.mp4"}) {
        test::writeFile(dir / name, y4m);
        try {
            openVideoReader(dir / name);
            ADD_FAILURE() << name << " was read";
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("YUV4MPEG pipe: videos must be MP4, MOV, Matroska, WebM or GIF"),
                      std::string::npos)
                << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
    // The allowed ones still read (every format Marbler writes: VideoRoundTrip).
    writeFrames(dir / "kept.webm", 25.0);
    EXPECT_NO_THROW(openVideoReader(dir / "kept.webm"));
}

} // namespace
} // namespace marbler
