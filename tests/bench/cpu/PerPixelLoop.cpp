// perpixel_render GENOME.marble.json OUT.ppm WIDTH
//
// The straightforward per-pixel loop, as a whole program to time against `marbler render`:
// for each pixel, the design point of its centre is run backward through the genome's inverse
// maps in plain scalar double code until it lands in an ink, one sample per pixel, on one
// std::thread per core (2 on the development machine; rows interleaved), and the image is
// written as a binary PPM (P6). No structure-of-arrays, no tiles, no vector code of its own:
// what a careful first program does.
// The formulas and their order of operations are genome-format.md's as genome/src/Tools.cpp
// writes them, so the colours are those of `marbler render --aa none` (bit for bit with
// MARBLER_KERNEL=avx2 or baseline; the AVX-512 kernel's drops may flip a pixel on an ink's
// edge). 2D genomes without a source image only.

#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Tools.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace marbler;

/// The palette index seen at (x, y) (-1: the background), `ops` in reverse time order.
[[gnu::always_inline]] inline int colorAt(const std::vector<PreparedOp>& ops, double x, double y) {
    for (const PreparedOp& op : ops) {
        const double dx = x - op.c.x, dy = y - op.c.y;
        switch (op.tool) {
        case Tool::Drop:
        case Tool::Spray: {
            const double len2 = dx * dx + dy * dy;
            if (len2 < op.r * op.r) return op.color;
            if (op.tool == Tool::Drop && len2 > 0.0) {
                const double factor = std::sqrt(std::max(0.0, 1.0 - op.rPow / len2));
                x = x + dx * (factor - 1.0);
                y = y + dy * (factor - 1.0);
            }
            break;
        }
        case Tool::Line:
        case Tool::Comb: {
            const double t = dx * op.n.x + dy * op.n.y;
            double d = std::abs(t);
            if (op.tool == Tool::Comb) {
                const double s = op.spacing, m = t - s * std::floor(t / s);
                d = 0.5 * s - std::abs(m - 0.5 * s);
            }
            const double l = op.alphaLambda / (d + op.lambda);
            x = x - l * op.m.x;
            y = y - l * op.m.y;
            break;
        }
        case Tool::Wave: {
            const double f = op.amp[0] * std::sin(op.freq[0] * (dx * op.n.x + dy * op.n.y) + op.phase[0]);
            x = x - f * op.m.x;
            y = y - f * op.m.y;
            break;
        }
        case Tool::Circle:
        case Tool::Vortex: {
            const double rho = std::sqrt(dx * dx + dy * dy);
            if (!(rho > 0.0)) break;
            const double d = op.tool == Tool::Vortex ? rho : std::abs(rho - op.r);
            const double theta = -(op.alphaLambda / (d + op.lambda)) / rho;
            const double c = std::cos(theta), s = std::sin(theta);
            x = op.c.x + (c * dx - s * dy);
            y = op.c.y + (s * dx + c * dy);
            break;
        }
        case Tool::Cylinder:
        case Tool::Sphere:
            break; // 3D only
        case Tool::Stretch:
        case Tool::Flow:
            break; // version 2: not in the benchmark's genomes
        case Tool::Stylus:
            break; // version 3: not in the benchmark's genomes
        }
    }
    return -1;
}

/// Rows first, first + step, ... of the image. Compiled for AVX-512, AVX2 and baseline x86-64
/// (the loader picks), as `marbler render`'s kernel is, so the comparison gives the plain loop
/// the same instructions.
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"))) void
renderRows(const Genome& genome, const std::vector<PreparedOp>& ops, int width, int height, int first,
           int step, std::uint8_t* rgb) {
    const double su = genome.size.x / width, sv = genome.size.y / height;
    for (int j = first; j < height; j += step) {
        std::uint8_t* out = rgb + std::size_t(j) * std::size_t(width) * 3;
        const double y = (j + 0.5) * sv;
        for (int i = 0; i < width; ++i, out += 3) {
            const int k = colorAt(ops, (i + 0.5) * su, y);
            const Color c = k >= 0 ? genome.palette[std::size_t(k)] : genome.background;
            out[0] = c.r;
            out[1] = c.g;
            out[2] = c.b;
        }
    }
}

int run(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: perpixel_render GENOME.marble.json OUT.ppm WIDTH\n");
        return 2;
    }
    const Genome genome = loadGenome(argv[1]);
    if (genome.dimension != 2 || genome.source)
        throw InputError(std::string(argv[1]) +
                         ": perpixel_render draws 2D genomes without a source image only");
    const int width = std::atoi(argv[3]);
    const int height = static_cast<int>(std::round(width / (genome.size.x / genome.size.y)));
    if (width < 1 || width > 65536 || height < 1 || height > 65536)
        throw InputError(std::string("WIDTH: '") + argv[3] +
                         "' is not a width from 1 to 65536 (or the height is not)");

    std::vector<PreparedOp> ops = prepare(genome);
    std::reverse(ops.begin(), ops.end());
    std::vector<std::uint8_t> rgb(std::size_t(width) * std::size_t(height) * 3);
    auto rows = [&](int first, int step) { renderRows(genome, ops, width, height, first, step, rgb.data()); };
    const int threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t)
        pool.emplace_back(rows, t, threads);
    rows(0, threads);
    for (std::thread& t : pool)
        t.join();

    std::FILE* file = std::fopen(argv[2], "wb");
    if (!file) throw RuntimeFailure(std::string("cannot write ") + argv[2]);
    std::fprintf(file, "P6\n%d %d\n255\n", width, height);
    const bool written = std::fwrite(rgb.data(), 1, rgb.size(), file) == rgb.size();
    if (std::fclose(file) != 0 || !written) throw RuntimeFailure(std::string("cannot write ") + argv[2]);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const InputError& e) {
        std::fprintf(stderr, "perpixel_render: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "perpixel_render: %s\n", e.what());
        return 1;
    }
}
