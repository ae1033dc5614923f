#!/usr/bin/env bash
# Replays a fuzz_mesh corpus through the mesh loader under valgrind, which sees assimp's own
# writes past its buffers (AddressSanitizer does not: assimp is Debian's, uninstrumented). Run it
# after every long fuzz_mesh run; exits 1 and keeps valgrind's report on an error.
#   fuzz/mesh-valgrind.sh [CORPUS-FOLDER]     (default: build-fuzz/corpus-mesh and fuzz/corpus-mesh)
set -euo pipefail
cd "$(dirname "$0")/.."
out=build-fuzz/mesh-replay
mkdir -p "$out"
g++ -std=c++20 -O1 -g fuzz/MeshReplay.cpp render/gl/src/Meshes.cpp render/gl/src/MeshFileCheck.cpp \
    -I genome/include -I render/include -I render/gl/include -I render/gl/src \
    -lassimp -o "$out/mesh_replay"
folders=("$@")
[ ${#folders[@]} -eq 0 ] && folders=(fuzz/corpus-mesh build-fuzz/corpus-mesh)
for folder in "${folders[@]}"; do
    [ -d "$folder" ] || continue
    if ! valgrind -q --error-exitcode=99 "$out/mesh_replay" "$folder" "$out/scratch" 2>"$out/valgrind.log"; then
        grep -B2 -A20 "Invalid\|uninitialised" "$out/valgrind.log" | head -60
        echo "mesh-valgrind: an error in $folder (the input before it is named by its '==' line):" \
            "$out/valgrind.log" >&2
        exit 1
    fi
    tail -1 "$out/valgrind.log"
done
