#!/usr/bin/env bash
# Fuzzes the genome loader: configures a clang build with libFuzzer, AddressSanitizer and
# UndefinedBehaviorSanitizer in build-fuzz, then runs fuzz_genome for the given seconds
# (default 60) from the committed corpus, fuzz_image (genomes inside PNG and TIFF images) for
# half as long from fuzz/corpus-image, and fuzz_source (a genome's source image through the
# allow-list and the decoder) and fuzz_mesh (a mesh file through its checks and assimp) for
# half as long each, from fuzz/corpus-source and fuzz/corpus-mesh, and fuzz_session (a breeding
# session file) and fuzz_recovery (an editor's recovery file, opened in the editor's document)
# for half as long each, from fuzz/corpus-session and fuzz/corpus-recovery. Exits non-zero on a
# finding; the crashing input is left in build-fuzz/findings/.
#   fuzz/run.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_TO_RUN=${1:-60}
# In CI (CI=true) the targets that are still young (fuzz_source, fuzz_mesh, fuzz_session,
# fuzz_recovery) replay their
# committed corpora, every finding included, instead of mutating: a new finding belongs to a
# developer's long run (fuzz/run.sh 600), not to a random failure of someone else's change.
YOUNG_TARGETS_RUN=(-max_total_time="$(( (SECONDS_TO_RUN + 1) / 2 ))")
[ "${CI:-}" = true ] && YOUNG_TARGETS_RUN=(-runs=0)
BUILD=build-fuzz

cmake -S . -B "$BUILD" -G Ninja \
    -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DMARBLER_FUZZ=ON -DMARBLER_SANITIZE=ON \
    -DMARBLER_BUILD_TESTS=OFF -DMARBLER_BUILD_GUI=OFF -DMARBLER_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$BUILD" --target fuzz_genome fuzz_image fuzz_source fuzz_mesh fuzz_session fuzz_recovery \
    -j "$(nproc)"

# New inputs go to a corpus under the build folder; the committed seeds are only read.
mkdir -p "$BUILD/corpus" "$BUILD/corpus-image" "$BUILD/corpus-source" "$BUILD/corpus-mesh" \
    "$BUILD/corpus-session" "$BUILD/corpus-recovery" "$BUILD/findings"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
"$BUILD/fuzz/fuzz_genome" "$BUILD/corpus" fuzz/corpus \
    -max_total_time="$SECONDS_TO_RUN" -max_len=65536 -rss_limit_mb=2048 -timeout=10 \
    -dict=fuzz/genome.dict -artifact_prefix="$BUILD/findings/" -print_final_stats=1
# Images: one allocation over 2 GiB is a finding, as for genomes, but the resident size may
# reach 4 GiB: AddressSanitizer keeps freed memory in quarantine, and one run here reached 2036
# MiB of the 2048 then allowed without any one allocation over it.
"$BUILD/fuzz/fuzz_image" "$BUILD/corpus-image" fuzz/corpus-image \
    -max_total_time="$(( (SECONDS_TO_RUN + 1) / 2 ))" -max_len=65536 -rss_limit_mb=4096 -malloc_limit_mb=2048 -timeout=10 \
    -artifact_prefix="$BUILD/findings/" -print_final_stats=1
# The young targets: NAME, corpus folder, then libFuzzer's limits. Qt's and assimp's own
# buffers are not leaks (fuzz/lsan.supp). Their first input loads the image module and its
# libraries (dlopen), which took over 10 s once on a busy machine: 30 s an input.
young() {
    local target=$1 corpus=$2
    shift 2
    LSAN_OPTIONS=suppressions=$PWD/fuzz/lsan.supp \
    "$BUILD/fuzz/$target" "$BUILD/$corpus" "fuzz/$corpus" \
        "${YOUNG_TARGETS_RUN[@]}" "$@" -timeout=30 \
        -artifact_prefix="$BUILD/findings/" -print_final_stats=1
}
# Source images: the decoder may hold a raster of up to 64 megapixels (768 MiB) and the reader's
# own buffer; one allocation over 2 GiB is a finding.
young fuzz_source corpus-source -max_len=65536 -rss_limit_mb=4096 -malloc_limit_mb=2048
# Meshes: within the caps (16 M vertices, 32 M triangles) assimp may allocate a few GiB for a
# file that announces that much honestly; inputs here are at most 64 KiB, so far less.
young fuzz_mesh corpus-mesh -max_len=65536 -rss_limit_mb=4096 -malloc_limit_mb=2048
# Sessions: a session may hold thousands of designs, but inputs here are at most 256 KiB (a
# real session of one generation is some 150 KiB); the parsed designs take a few times that.
# One allocation over 1 GiB is a finding.
young fuzz_session corpus-session -max_len=262144 -rss_limit_mb=2048 -malloc_limit_mb=1024
# Recovery files: one design (at most 2 x 16 MiB, Recovery.cpp), read and opened in the
# editor's document twice; inputs here are at most 64 KiB. One allocation over 1 GiB is a finding.
young fuzz_recovery corpus-recovery -max_len=65536 -rss_limit_mb=2048 -malloc_limit_mb=1024
