// marbler-video.so: the one file of Marbler that sees FFmpeg. Loaded on first use by
// render/src/Video.cpp to write the frames of `marbler animate` and `marbler video` as .mp4
// (H.264 by libx264, else MPEG-4 part 2), .webm (VP9 by libvpx, else VP8), .gif (one palette for
// the whole file, by libavfilter's palettegen and paletteuse) or animated .webp (libwebp), and to
// decode the frames of common videos: MP4/MOV, Matroska/WebM and GIF containers holding H.264,
// H.265, VP8, VP9, AV1, MPEG-4 part 2 or GIF video, and nothing else FFmpeg reads.

#include "VideoModule.h"
#include "marbler/Error.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavformat/avformat.h>
#include <libavutil/avstring.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <vector>

namespace marbler::detail {
namespace {

/// Frames larger than this (64 megapixels) are refused when reading, so a hostile file that
/// claims a huge size cannot make the reader allocate gigabytes.
constexpr std::int64_t MaxFramePixels = std::int64_t(1) << 26;

/// The demuxers and decoders a video may reach: the common containers and codecs of cameras,
/// phones and the web. FFmpeg's dozens of others (and its network and concat protocols) are
/// never handed a file a stranger sent.
constexpr const char* AllowedDemuxers = "mov,mp4,m4a,3gp,3g2,mj2,matroska,webm,gif";
constexpr const char* AllowedContainers = "MP4, MOV, Matroska, WebM or GIF";
constexpr AVCodecID AllowedCodecs[] = {AV_CODEC_ID_H264, AV_CODEC_ID_HEVC,  AV_CODEC_ID_VP8, AV_CODEC_ID_VP9,
                                       AV_CODEC_ID_AV1,  AV_CODEC_ID_MPEG4, AV_CODEC_ID_GIF};
constexpr const char* AllowedCodecNames = "H.264, H.265, VP8, VP9, AV1, MPEG-4 part 2 or GIF";

std::string errorText(int code) {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return text;
}

/// An output context, its file closed first when still open.
struct FormatFree {
    void operator()(AVFormatContext* c) const {
        if (c->pb && !(c->oformat->flags & AVFMT_NOFILE)) avio_closep(&c->pb);
        avformat_free_context(c);
    }
};
struct InputClose {
    void operator()(AVFormatContext* c) const { avformat_close_input(&c); }
};
struct CodecFree {
    void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
};
struct FrameFree {
    void operator()(AVFrame* f) const { av_frame_free(&f); }
};
struct PacketFree {
    void operator()(AVPacket* p) const { av_packet_free(&p); }
};
struct GraphFree {
    void operator()(AVFilterGraph* g) const { avfilter_graph_free(&g); }
};
struct SwsFree {
    void operator()(SwsContext* s) const { sws_freeContext(s); }
};
using FramePtr = std::unique_ptr<AVFrame, FrameFree>;
using PacketPtr = std::unique_ptr<AVPacket, PacketFree>;

/// The encoders a format may use, best first: the first this FFmpeg has is taken.
struct FormatChoice {
    const char* muxer;
    std::vector<const char*> encoders;
};

FormatChoice choiceFor(const std::string& extension) {
    if (extension == ".mp4") return {"mp4", {"libx264", "libopenh264", "mpeg4"}};
    if (extension == ".webm") return {"webm", {"libvpx-vp9", "libvpx"}};
    if (extension == ".gif") return {"gif", {"gif"}};
    return {"webp", {"libwebp_anim"}};
}

const AVCodec* findEncoder(const FormatChoice& choice) {
    for (const char* name : choice.encoders)
        if (const AVCodec* codec = avcodec_find_encoder_by_name(name)) return codec;
    return nullptr;
}

std::string encoderList(const FormatChoice& choice) {
    std::string names;
    for (const char* name : choice.encoders)
        names += (names.empty() ? "" : ", ") + std::string(name);
    return names;
}

/// An FFmpeg writer. Frames arrive as 8-bit sRGB RGB and are converted by libswscale to what the
/// encoder takes (4:2:0 YUV with the BT.601 matrix for H.264, MPEG-4 and VP9; BGRA for WebP,
/// which converts itself); GIF frames go through a filter graph that finds one palette from
/// every frame (palettegen) and maps each frame onto it (paletteuse, ordered dithering, which
/// stays still from frame to frame where error diffusion shimmers). Frame k is stamped k in a
/// time base of 1/fps (fps as a fraction), so the rate is exact.
class FfmpegWriter final : public VideoWriter {
public:
    explicit FfmpegWriter(const VideoTarget& target)
        : mTarget(target) {
        const FormatChoice choice = choiceFor(target.extension);
        const AVCodec* codec = findEncoder(choice);
        if (!codec)
            throw RuntimeFailure("cannot write '" + target.displayName +
                                 "': this FFmpeg has no encoder for " + target.extension + " (looked for " +
                                 encoderList(choice) + ")");
        AVFormatContext* format = nullptr;
        int code = avformat_alloc_output_context2(&format, nullptr, choice.muxer, target.file.c_str());
        if (code < 0 || !format) fail("no " + std::string(choice.muxer) + " muxer: " + errorText(code));
        mFormat.reset(format);

        mGif = target.extension == ".gif";
        const bool webp = target.extension == ".webp";
        const bool vp9 = std::strcmp(codec->name, "libvpx-vp9") == 0;
        mPixelFormat = mGif ? AV_PIX_FMT_PAL8 : webp ? AV_PIX_FMT_BGRA : AV_PIX_FMT_YUV420P;
        // 4:2:0 needs even sides in H.264 and MPEG-4 (VP9 keeps odd ones): an odd side is
        // encoded one pixel larger, its last column or row repeated.
        const bool evenSides = mPixelFormat == AV_PIX_FMT_YUV420P && !vp9;
        mCodedWidth = evenSides ? (target.width + 1) & ~1 : target.width;
        mCodedHeight = evenSides ? (target.height + 1) & ~1 : target.height;

        const AVRational rate = av_d2q(target.fps, 100000);
        mTimeBase = av_inv_q(rate);
        mCodec.reset(avcodec_alloc_context3(codec));
        if (!mCodec) fail("out of memory");
        AVCodecContext* c = mCodec.get();
        c->width = mCodedWidth;
        c->height = mCodedHeight;
        c->time_base = mTimeBase;
        c->framerate = rate;
        c->pix_fmt = mPixelFormat;
        c->sample_aspect_ratio = AVRational{1, 1};
        if (mPixelFormat == AV_PIX_FMT_YUV420P) {
            // What libswscale's default conversion writes: sRGB primaries, the BT.601 matrix,
            // limited range.
            c->color_primaries = AVCOL_PRI_BT709;
            c->color_trc = AVCOL_TRC_IEC61966_2_1;
            c->colorspace = AVCOL_SPC_SMPTE170M;
            c->color_range = AVCOL_RANGE_MPEG;
            c->gop_size = 250;
        }
        if (mFormat->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        AVDictionary* options = nullptr;
        if (std::strcmp(codec->name, "libx264") == 0) {
            av_dict_set(&options, "crf", "18", 0);
            av_dict_set(&options, "preset", "medium", 0);
        } else if (std::strcmp(codec->name, "mpeg4") == 0) {
            c->bit_rate = 0;
            c->flags |= AV_CODEC_FLAG_QSCALE;
            c->global_quality = FF_QP2LAMBDA * 3;
        } else if (vp9 || std::strcmp(codec->name, "libvpx") == 0) {
            c->bit_rate = 0;
            av_dict_set(&options, "crf", "24", 0);
            av_dict_set(&options, "b", "0", 0);
            av_dict_set(&options, "deadline", "good", 0);
            av_dict_set(&options, "cpu-used", "4", 0);
            av_dict_set(&options, "row-mt", "1", 0);
        } else if (webp) {
            av_dict_set(&options, "quality", "90", 0);
            av_dict_set(&options, "loop", "0", 0);
        }
        code = avcodec_open2(c, codec, &options);
        av_dict_free(&options);
        if (code < 0) fail("cannot open the " + std::string(codec->name) + " encoder: " + errorText(code));

        mStream = avformat_new_stream(mFormat.get(), nullptr);
        if (!mStream) fail("out of memory");
        mStream->time_base = mTimeBase;
        mStream->avg_frame_rate = rate;
        mStream->r_frame_rate = rate;
        code = avcodec_parameters_from_context(mStream->codecpar, c);
        if (code < 0) fail(errorText(code));

        code = avio_open(&mFormat->pb, target.file.c_str(), AVIO_FLAG_WRITE);
        if (code < 0) fail(errorText(code));
        AVDictionary* muxerOptions = nullptr;
        if (choice.muxer == std::string("mp4")) av_dict_set(&muxerOptions, "movflags", "+faststart", 0);
        if (mGif) av_dict_set(&muxerOptions, "loop", "0", 0);
        code = avformat_write_header(mFormat.get(), &muxerOptions);
        av_dict_free(&muxerOptions);
        if (code < 0) fail("cannot start the file: " + errorText(code));

        mFrame.reset(av_frame_alloc());
        mPacket.reset(av_packet_alloc());
        if (!mFrame || !mPacket) fail("out of memory");
        if (mGif) {
            openPaletteGraph();
        } else {
            mFrame->format = mPixelFormat;
            mFrame->width = mCodedWidth;
            mFrame->height = mCodedHeight;
            if (av_frame_get_buffer(mFrame.get(), 0) < 0) fail("out of memory");
            mScale.reset(sws_getContext(
                mCodedWidth, mCodedHeight, AV_PIX_FMT_RGB24, mCodedWidth, mCodedHeight, mPixelFormat,
                SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr, nullptr));
            if (!mScale) fail("no conversion from RGB to the encoder's pixels");
        }
    }

    void addFrame(const std::uint8_t* rgb, std::size_t stride) override {
        if (mGif) {
            FramePtr frame(av_frame_alloc());
            if (!frame) fail("out of memory");
            frame->format = AV_PIX_FMT_RGB24;
            frame->width = mTarget.width;
            frame->height = mTarget.height;
            if (av_frame_get_buffer(frame.get(), 0) < 0) fail("out of memory");
            for (int y = 0; y < mTarget.height; ++y)
                std::memcpy(frame->data[0] + std::size_t(y) * std::size_t(frame->linesize[0]),
                            rgb + std::size_t(y) * stride, std::size_t(mTarget.width) * 3);
            frame->pts = mNext++;
            int code = av_buffersrc_add_frame_flags(mSource, frame.get(), AV_BUFFERSRC_FLAG_KEEP_REF);
            if (code < 0) fail("cannot queue a frame for the palette: " + errorText(code));
            return;
        }
        const std::uint8_t* source = rgb;
        std::size_t sourceStride = stride;
        if (mCodedWidth != mTarget.width || mCodedHeight != mTarget.height) {
            // The odd side padded with its last column or row.
            const std::size_t rowBytes = std::size_t(mCodedWidth) * 3;
            mPadded.resize(rowBytes * std::size_t(mCodedHeight));
            for (int y = 0; y < mCodedHeight; ++y) {
                const std::uint8_t* from = rgb + std::size_t(std::min(y, mTarget.height - 1)) * stride;
                std::uint8_t* to = mPadded.data() + std::size_t(y) * rowBytes;
                std::memcpy(to, from, std::size_t(mTarget.width) * 3);
                for (int x = mTarget.width; x < mCodedWidth; ++x)
                    std::memcpy(to + x * 3, from + (mTarget.width - 1) * 3, 3);
            }
            source = mPadded.data();
            sourceStride = rowBytes;
        }
        int code = av_frame_make_writable(mFrame.get());
        if (code < 0) fail(errorText(code));
        const std::uint8_t* planes[1] = {source};
        const int strides[1] = {static_cast<int>(sourceStride)};
        sws_scale(mScale.get(), planes, strides, 0, mCodedHeight, mFrame->data, mFrame->linesize);
        mFrame->pts = mNext++;
        encode(mFrame.get());
    }

    void finish() override {
        if (mGif) {
            int code = av_buffersrc_add_frame_flags(mSource, nullptr, 0);
            if (code < 0) fail(errorText(code));
            FramePtr frame(av_frame_alloc());
            if (!frame) fail("out of memory");
            while ((code = av_buffersink_get_frame(mSink, frame.get())) >= 0) {
                frame->pict_type = AV_PICTURE_TYPE_NONE;
                encode(frame.get());
                av_frame_unref(frame.get());
            }
            if (code != AVERROR_EOF) fail("the palette filter failed: " + errorText(code));
        }
        encode(nullptr);
        // The GIF muxer times a frame by the next one's stamp and, without this, repeats the
        // last delay but one for the last frame.
        if (mGif && mNext > 0)
            av_opt_set_int(mFormat->priv_data, "final_delay",
                           av_rescale_q(mNext, mTimeBase, mStream->time_base) -
                               av_rescale_q(mNext - 1, mTimeBase, mStream->time_base),
                           0);
        int code = av_write_trailer(mFormat.get());
        if (code < 0) fail(errorText(code));
        code = avio_closep(&mFormat->pb);
        if (code < 0) fail(errorText(code));
    }

private:
    [[noreturn]] void fail(const std::string& reason) const {
        throw RuntimeFailure("cannot write '" + mTarget.displayName + "': " + reason);
    }

    /// buffer -> split -> palettegen (one palette from all frames) and paletteuse -> buffersink.
    void openPaletteGraph() {
        mGraph.reset(avfilter_graph_alloc());
        if (!mGraph) fail("out of memory");
        char arguments[256];
        std::snprintf(arguments, sizeof arguments,
                      "video_size=%dx%d:pix_fmt=%d:time_base=%d/%d:pixel_aspect=1/1", mTarget.width,
                      mTarget.height, int(AV_PIX_FMT_RGB24), mTimeBase.num, mTimeBase.den);
        int code = avfilter_graph_create_filter(&mSource, avfilter_get_by_name("buffer"), "in", arguments,
                                                nullptr, mGraph.get());
        if (code < 0) fail("no buffer filter: " + errorText(code));
        code = avfilter_graph_create_filter(&mSink, avfilter_get_by_name("buffersink"), "out", nullptr,
                                            nullptr, mGraph.get());
        if (code < 0) fail("no buffersink filter: " + errorText(code));
        AVFilterInOut* outputs = avfilter_inout_alloc();
        AVFilterInOut* inputs = avfilter_inout_alloc();
        if (!outputs || !inputs) {
            avfilter_inout_free(&outputs);
            avfilter_inout_free(&inputs);
            fail("out of memory");
        }
        outputs->name = av_strdup("in");
        outputs->filter_ctx = mSource;
        inputs->name = av_strdup("out");
        inputs->filter_ctx = mSink;
        code = avfilter_graph_parse_ptr(mGraph.get(),
                                        "split[a][b];[a]palettegen=stats_mode=full:reserve_transparent=0[p];"
                                        "[b][p]paletteuse=dither=bayer:bayer_scale=3",
                                        &inputs, &outputs, nullptr);
        avfilter_inout_free(&outputs);
        avfilter_inout_free(&inputs);
        if (code < 0) fail("cannot build the palette filters: " + errorText(code));
        code = avfilter_graph_config(mGraph.get(), nullptr);
        if (code < 0) fail("cannot set up the palette filters: " + errorText(code));
    }

    /// Sends a frame (nullptr: the end) to the encoder and writes the packets it gives.
    void encode(const AVFrame* frame) {
        int code = avcodec_send_frame(mCodec.get(), frame);
        if (code < 0) fail("cannot encode a frame: " + errorText(code));
        for (;;) {
            code = avcodec_receive_packet(mCodec.get(), mPacket.get());
            if (code == AVERROR(EAGAIN) || code == AVERROR_EOF) return;
            if (code < 0) fail("cannot encode a frame: " + errorText(code));
            // Each frame lasts one tick of 1/fps: its duration in the stream's time base is the
            // distance to the next frame's stamp there, so a format of coarser ticks (GIF's
            // hundredths) keeps the rate on average (12 fps: 8, 9, 8, 8, 9, ... hundredths).
            const std::int64_t pts = mPacket->pts;
            av_packet_rescale_ts(mPacket.get(), mTimeBase, mStream->time_base);
            if (pts != AV_NOPTS_VALUE)
                mPacket->duration = av_rescale_q(pts + 1, mTimeBase, mStream->time_base) -
                                    av_rescale_q(pts, mTimeBase, mStream->time_base);
            mPacket->stream_index = mStream->index;
            code = av_interleaved_write_frame(mFormat.get(), mPacket.get());
            if (code < 0) fail(errorText(code));
        }
    }

    VideoTarget mTarget;
    std::unique_ptr<AVFormatContext, FormatFree> mFormat;
    std::unique_ptr<AVCodecContext, CodecFree> mCodec;
    std::unique_ptr<SwsContext, SwsFree> mScale;
    std::unique_ptr<AVFilterGraph, GraphFree> mGraph;
    AVFilterContext* mSource = nullptr; ///< owned by mGraph
    AVFilterContext* mSink = nullptr;   ///< owned by mGraph
    AVStream* mStream = nullptr;        ///< owned by mFormat
    FramePtr mFrame;
    PacketPtr mPacket;
    std::vector<std::uint8_t> mPadded;
    AVRational mTimeBase{1, 25};
    AVPixelFormat mPixelFormat = AV_PIX_FMT_YUV420P;
    int mCodedWidth = 0, mCodedHeight = 0;
    std::int64_t mNext = 0;
    bool mGif = false;
};

/// Refuses, naming it, a file whose container is not on the allow-list, as FFmpeg's probe (the
/// same that avformat_open_input runs) tells it from the first bytes.
void refuseOtherContainers(const std::string& file, const std::string& name) {
    std::vector<unsigned char> head(4096 + AVPROBE_PADDING_SIZE, 0);
    std::FILE* f = std::fopen(file.c_str(), "rb");
    if (!f) throw InputError(name + ": cannot read: " + std::strerror(errno));
    const std::size_t got = std::fread(head.data(), 1, 4096, f);
    std::fclose(f);
    AVProbeData probe{};
    probe.filename = file.c_str();
    probe.buf = head.data();
    probe.buf_size = int(got);
    int score = 0;
    const AVInputFormat* found = av_probe_input_format3(&probe, 1, &score);
    if (!found || av_match_list(found->name, AllowedDemuxers, ',') > 0) return; // let FFmpeg say the rest
    throw InputError(name + ": " + (found->long_name ? found->long_name : found->name) + ": videos must be " +
                     AllowedContainers);
}

/// An FFmpeg reader: the best video stream of the file, decoded and converted to RGB by
/// libswscale with the matrix and range the stream declares.
class FfmpegReader final : public VideoReader {
public:
    FfmpegReader(const std::string& file, const std::string& name)
        : mName(name) {
        refuseOtherContainers(file, name);
        AVFormatContext* format = avformat_alloc_context();
        if (!format) throw RuntimeFailure("out of memory");
        // The same lists again inside FFmpeg, which enforces them for whatever it opens itself.
        format->format_whitelist = av_strdup(AllowedDemuxers);
        format->protocol_whitelist = av_strdup("file");
        int code = avformat_open_input(&format, file.c_str(), nullptr, nullptr); // frees it on failure
        if (code < 0) throw InputError(name + ": not a video Marbler reads (" + errorText(code) + ")");
        mFormat.reset(format);
        code = avformat_find_stream_info(format, nullptr);
        if (code < 0) throw InputError(name + ": not a video FFmpeg reads (" + errorText(code) + ")");
        const AVCodec* codec = nullptr;
        mStream = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
        if (mStream < 0 || !codec) throw InputError(name + ": holds no video FFmpeg can decode");
        const AVStream* stream = format->streams[mStream];
        const AVCodecParameters* parameters = stream->codecpar;
        if (std::find(std::begin(AllowedCodecs), std::end(AllowedCodecs), parameters->codec_id) ==
            std::end(AllowedCodecs)) {
            const AVCodecDescriptor* d = avcodec_descriptor_get(parameters->codec_id);
            throw InputError(name + ": its video is " + (d ? d->long_name : "of an unknown codec") +
                             ": videos must be " + AllowedCodecNames);
        }
        if (parameters->width < 1 || parameters->height < 1 ||
            std::int64_t(parameters->width) * parameters->height > MaxFramePixels)
            throw InputError(name + ": unsupported frame size " + std::to_string(parameters->width) + "x" +
                             std::to_string(parameters->height));
        mCodec.reset(avcodec_alloc_context3(codec));
        if (!mCodec) throw RuntimeFailure("out of memory");
        code = avcodec_parameters_to_context(mCodec.get(), parameters);
        if (code < 0) throw InputError(name + ": " + errorText(code));
        mCodec->thread_count = 0;
        code = avcodec_open2(mCodec.get(), codec, nullptr);
        if (code < 0)
            throw InputError(name + ": cannot open its " + std::string(codec->name) +
                             " decoder: " + errorText(code));
        mWidth = parameters->width;
        mHeight = parameters->height;
        AVRational rate = stream->avg_frame_rate;
        if (rate.num <= 0 || rate.den <= 0) rate = stream->r_frame_rate;
        mFps = rate.num > 0 && rate.den > 0 ? av_q2d(rate) : 25.0;
        mFrame.reset(av_frame_alloc());
        mPacket.reset(av_packet_alloc());
        if (!mFrame || !mPacket) throw RuntimeFailure("out of memory");
    }

    int width() const override { return mWidth; }
    int height() const override { return mHeight; }
    double fps() const override { return mFps; }

    bool nextFrame(std::vector<std::uint8_t>& rgb) override {
        for (;;) {
            int code = avcodec_receive_frame(mCodec.get(), mFrame.get());
            if (code >= 0) {
                convert(rgb);
                av_frame_unref(mFrame.get());
                return true;
            }
            if (code == AVERROR_EOF) return false;
            if (code != AVERROR(EAGAIN)) fail(code);
            if (mDraining) return false;
            // Feed the decoder the next packet of the stream, or the end.
            for (;;) {
                code = av_read_frame(mFormat.get(), mPacket.get());
                if (code == AVERROR_EOF) {
                    mDraining = true;
                    code = avcodec_send_packet(mCodec.get(), nullptr);
                    if (code < 0 && code != AVERROR_EOF) fail(code);
                    break;
                }
                if (code < 0) fail(code);
                if (mPacket->stream_index != mStream) {
                    av_packet_unref(mPacket.get());
                    continue;
                }
                code = avcodec_send_packet(mCodec.get(), mPacket.get());
                av_packet_unref(mPacket.get());
                if (code < 0 && code != AVERROR(EAGAIN)) fail(code);
                break;
            }
        }
    }

private:
    [[noreturn]] void fail(int code) const {
        throw RuntimeFailure(mName + ": cannot decode a frame: " + errorText(code));
    }

    void convert(std::vector<std::uint8_t>& rgb) {
        const AVFrame* f = mFrame.get();
        if (f->width != mWidth || f->height != mHeight)
            throw RuntimeFailure(mName + ": the frame size changes mid-stream (" + std::to_string(mWidth) +
                                 "x" + std::to_string(mHeight) + " to " + std::to_string(f->width) + "x" +
                                 std::to_string(f->height) + ")");
        const auto format = static_cast<AVPixelFormat>(f->format);
        mScale.reset(sws_getCachedContext(
            mScale.release(), mWidth, mHeight, format, mWidth, mHeight, AV_PIX_FMT_RGB24,
            SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr, nullptr));
        if (!mScale) throw RuntimeFailure(mName + ": no conversion of its pixels to RGB");
        const int matrix = f->colorspace == AVCOL_SPC_BT709 ? SWS_CS_ITU709
                           : f->colorspace == AVCOL_SPC_BT2020_NCL || f->colorspace == AVCOL_SPC_BT2020_CL
                               ? SWS_CS_BT2020
                               : SWS_CS_DEFAULT;
        const bool fullRange = f->color_range == AVCOL_RANGE_JPEG || format == AV_PIX_FMT_YUVJ420P ||
                               format == AV_PIX_FMT_YUVJ422P || format == AV_PIX_FMT_YUVJ444P;
        int* inverse = nullptr;
        int* table = nullptr;
        int sourceRange = 0, destinationRange = 0, brightness = 0, contrast = 0, saturation = 0;
        if (sws_getColorspaceDetails(mScale.get(), &inverse, &sourceRange, &table, &destinationRange,
                                     &brightness, &contrast, &saturation) >= 0)
            sws_setColorspaceDetails(mScale.get(), sws_getCoefficients(matrix), fullRange ? 1 : 0, table,
                                     destinationRange, brightness, contrast, saturation);
        rgb.resize(std::size_t(mWidth) * std::size_t(mHeight) * 3);
        std::uint8_t* planes[1] = {rgb.data()};
        const int strides[1] = {mWidth * 3};
        sws_scale(mScale.get(), f->data, f->linesize, 0, mHeight, planes, strides);
    }

    std::string mName;
    std::unique_ptr<AVFormatContext, InputClose> mFormat;
    std::unique_ptr<AVCodecContext, CodecFree> mCodec;
    std::unique_ptr<SwsContext, SwsFree> mScale;
    FramePtr mFrame;
    PacketPtr mPacket;
    int mStream = -1;
    int mWidth = 0, mHeight = 0;
    double mFps = 25.0;
    bool mDraining = false;
};

class FfmpegModule final : public VideoModule {
public:
    // FFmpeg's own log stays silent: every failure reaches the user as one line of ours.
    FfmpegModule() { av_log_set_level(AV_LOG_QUIET); }

    std::unique_ptr<VideoWriter> openWriter(const VideoTarget& target) override {
        return std::make_unique<FfmpegWriter>(target);
    }

    std::unique_ptr<VideoReader> openReader(const std::string& file, const std::string& name) override {
        return std::make_unique<FfmpegReader>(file, name);
    }

    std::string describe() const override {
        std::string text;
        for (const char* extension : {".mp4", ".webm", ".gif", ".webp"}) {
            const AVCodec* codec = findEncoder(choiceFor(extension));
            text += (text.empty() ? "" : "; ") + std::string(extension + 1) + ": " +
                    (codec ? std::string(codec->name) : "missing");
        }
        return text + " (libavcodec " + AV_STRINGIFY(LIBAVCODEC_VERSION) + ", libavformat " +
               AV_STRINGIFY(LIBAVFORMAT_VERSION) + ")";
    }
};

} // namespace
} // namespace marbler::detail

extern "C" __attribute__((visibility("default"))) marbler::detail::VideoModule* marbler_video_module() {
    static marbler::detail::FfmpegModule module;
    return &module;
}
