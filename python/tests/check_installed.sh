#!/usr/bin/env bash
# check_installed.sh BUILD_DIR PYTHON MODULE_DIR WORK_DIR: installs whiskermap into a scratch
# prefix and imports the installed module from there: its libraries are found through its
# relative RPATH, and it builds a map from the installed share/whiskermap/config.
set -euo pipefail
build=$1 python=$2 moddir=$3 work=$4
rm -rf "$work"; mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
ls "$work/prefix/$moddir"/whiskermap*.so >/dev/null
cd "$work"
out=$(WHISKERMAP_CONFIG_DIR="$work/prefix/share/whiskermap/config" PYTHONPATH="$work/prefix/$moddir" "$python" -c '
import whiskermap as wm
assert wm.__file__.startswith("'"$work"'/prefix/"), wm.__file__
m = wm.Map()
print(wm.__version__, m.config, m.mode)')
echo "$out"
[[ "$out" == *" $work/prefix/share/whiskermap/config/whisker-map.ini lasting" ]]
echo "ok: the installed module imports and maps with the installed config"
