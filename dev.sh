#!/usr/bin/env bash
# Marbler's two developer commands (see README.md):
#   ./dev.sh start   install what is missing, build, and start the workbench
#   ./dev.sh test    install what is missing, build, and run every test
# Both work on a fresh Debian 12 machine as root (or with sudo available). And for people who
# install Marbler rather than build it (docs/packaging.md):
#   ./dev.sh package build the Debian package build-package/marbler_VERSION_amd64.deb
set -euo pipefail
cd "$(dirname "$0")"

# What the build needs, and why where it is not obvious. Every package config that CMake's
# find_package loads was read for imported targets that point at files of other packages:
# assimp's target links /usr/lib/x86_64-linux-gnu/libz.so (zlib1g-dev), which libassimp-dev does
# not depend on. OpenImageIO is found through pkg-config instead of its CMake config, which
# declares its command-line tools as imported targets (iconvert, iv, ...) and so fails unless
# openimageio-tools and Qt 5 are installed.
PACKAGES=(
    build-essential cmake ninja-build pkg-config
    clang-format git                             # the format check, first in ./dev.sh test
    clang libclang-rt-14-dev                     # the fuzzer build (fuzz/run.sh)
    qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev libgl1-mesa-dev libgl1-mesa-dri libegl1
    libglm-dev nlohmann-json3-dev
    libopenimageio-dev                           # EXR, JPEG and other formats; source images
    libpng-dev libtiff-dev                       # PNG and TIFF, written directly (fast start)
    libpolyclipping-dev                          # polygon clipping: the SVG's inks knocked out
    liblcms2-dev                                 # LittleCMS: render --icc converts to a printer's CMYK profile
    libavcodec-dev libavformat-dev libavutil-dev  # videos and animated images (marbler-video.so)
    libswscale-dev libavfilter-dev               # pixel conversion; the GIF palette filters
    libwebp-dev                                  # the tests read animated WebP back with libwebpdemux
    libassimp-dev zlib1g-dev                     # mesh files; zlib for assimp's CMake target
    libgtest-dev libgmock-dev libbenchmark-dev
    xvfb xauth                                   # a virtual display for the GL and window tests
    librsvg2-bin                                 # rsvg-convert: the svg tests rasterise `marbler svg` output
    lintian appstream desktop-file-utils         # the package's checks (packaging/check-package.sh)
    file                                         # CPack's shlibdeps finds the binaries with it
    groff-base bash-completion                   # the manual page and completion tests (tests/packaging)
    qt6-l10n-tools                               # lrelease compiles the window's translations (translations/)
)
JOBS=$(nproc)

install_missing() {
    local missing=()
    for p in "${PACKAGES[@]}"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    echo "== installing: ${missing[*]}"
    local sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# build DIR [cmake options...]
build() {
    local dir=$1
    shift
    cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@" >/dev/null
    cmake --build "$dir" -j "$JOBS"
}

# Every test under a virtual display, so the GL and window tests get Mesa's llvmpipe OpenGL
# and must run (MARBLER_REQUIRE_GL turns a missing GL context into a failure, not a skip).
# -noreset: by default Xvfb resets whenever its last client disconnects, and a test that
# connects during the reset fails with "could not connect to display" (seen under load).
run_ctest() {
    local dir=$1
    shift
    MARBLER_REQUIRE_GL=1 xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
        ctest --test-dir "$dir" --output-on-failure -j "$JOBS" "$@"
}

# The tree stays as the committed .clang-format writes it: every tracked C++ source checked,
# in a second or two, before anything is built.
check_format() {
    echo "== format (clang-format $(clang-format --version | grep -o '[0-9][0-9.]*' | head -1))"
    local bad
    bad=$(git ls-files '*.cpp' '*.h' | grep -v '^tests/data/' | xargs clang-format --dry-run 2>&1 |
        grep -o '^[^:]*\.\(cpp\|h\):' | sort -u | tr -d ':') || true
    if [ -n "$bad" ]; then
        echo "not formatted with .clang-format (run: clang-format -i FILE):" >&2
        echo "$bad" >&2
        exit 1
    fi
}

# package DIR: the Debian package of the build in DIR, packed by CPack with the prefix /usr
# (packaging/Packaging.cmake), then its contents and metadata checked.
package() {
    local dir=$1
    rm -f "$dir"/marbler_*.deb
    (cd "$dir" && cpack -G DEB >cpack.log 2>&1) || { cat "$dir/cpack.log"; return 1; }
    bash packaging/check-package.sh "$dir"/marbler_*_amd64.deb
}

case "${1:-}" in
package)
    install_missing
    # A tree of its own without tests or benchmarks, configured for /usr, with the project's
    # release flags (RelWithDebInfo: what every test runs; the package's files are stripped).
    build build-package -DCMAKE_INSTALL_PREFIX=/usr -DMARBLER_BUILD_TESTS=OFF -DMARBLER_BUILD_BENCHMARKS=OFF
    package build-package
    echo "== $(ls build-package/marbler_*_amd64.deb): install it with  apt install ./$(ls build-package/marbler_*_amd64.deb)"
    ;;
start)
    install_missing
    build build
    shift
    exec ./build/app/marbler "$@"
    ;;
test)
    install_missing
    check_format
    echo "== release build and tests"
    build build
    run_ctest build
    echo "== the Debian package, packed from that build and checked"
    package build
    echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
    # The sanitisers watch the code that reads what users and strangers hand Marbler (genome
    # files, images, meshes, videos), the renderers and breeding: the libraries, the CPU renderer
    # and the command line, with all of their tests; and the window's tests of what holds the
    # user's work (label `work`: the editor's document, history and recovery, the workbench's
    # sessions and history). Only those window tests are built here (MARBLER_GUI_TESTS=work): the
    # window's libraries and four test programs add some minutes on 2 cores, where every window
    # and GL test would add about 15 and take CI past its 40 (docs/performance.md). The other
    # window and GL tests run in the release build above; MARBLER_SANITIZE_GUI=1 builds and runs
    # all of them here too.
    gui_tests=work
    [ "${MARBLER_SANITIZE_GUI:-0}" = 1 ] && gui_tests=all
    build build-asan -DMARBLER_SANITIZE=ON -DMARBLER_BUILD_BENCHMARKS=OFF -DMARBLER_BUILD_GUI=ON \
        -DMARBLER_GUI_TESTS=$gui_tests
    export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
    # Leaks are checked everywhere but in the tests that load Mesa's GL driver, whose own
    # buffers LeakSanitizer cannot name once the driver is unloaded at exit.
    ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp \
        run_ctest build-asan -LE "gl|gui"
    ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 run_ctest build-asan -L "gl|gui"
    echo "== fuzzing the genome loader briefly"
    ./fuzz/run.sh 30
    echo "== all tests passed"
    ;;
*)
    echo "usage: $0 start|test|package" >&2
    exit 2
    ;;
esac
