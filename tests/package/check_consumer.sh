#!/usr/bin/env bash
# check_consumer.sh BUILD_DIR SRC_DIR WORK_DIR: installs whiskermap into a scratch prefix,
# builds tests/package/consumer against it with find_package(whiskermap), and runs it.
set -euo pipefail
build=$1 src=$2 work=$3
rm -rf "$work"; mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
# A sanitizer build's libraries need the consumer built the same way (scripts/sanitize-tests.sh).
cmake -S "$src/tests/package/consumer" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
      -DCMAKE_BUILD_TYPE=Release ${WHISKERMAP_CONSUMER_CMAKE_ARGS:-} >/dev/null
cmake --build "$work/build" >/dev/null
out=$("$work/build/consumer" "$src/datasets/paper_arena/default.rawlog")
echo "$out"
[[ "$out" == sweeps=400\ shapelets=* ]]
# The installed app runs and finds its installed config presets.
WHISKERMAP_CONFIG_DIR= "$work/prefix/bin/whisker-sim" -q -w "$src/config/worlds/paper_arena.ini" \
  --noise very-noisy -o "$work/x.rawlog"
test -s "$work/x.rawlog"
echo "ok: installed package builds a consumer and runs"
