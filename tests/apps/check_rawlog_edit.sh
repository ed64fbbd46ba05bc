#!/usr/bin/env bash
# check_rawlog_edit.sh PLUGIN RAWLOG EXPECTED_OBJECTS: stock rawlog-edit, given our library
# as a plugin, must read every object of RAWLOG (it exits 0 even when it stops early, so
# count) and must not meet an unregistered class.
set -euo pipefail
plugin=$1 rawlog=$2 expected=$3
command -v rawlog-edit >/dev/null || { echo "rawlog-edit not installed (scripts/install-deps.sh --tools)"; exit 1; }
# In a sanitizer build the plugin needs the sanitizer runtime preloaded (scripts/sanitize-tests.sh).
out=$(LD_PRELOAD="${WHISKERMAP_TOOL_PRELOAD:-}" rawlog-edit -p "$plugin" --info -i "$rawlog" 2>&1 </dev/null)
if grep -q "not registered" <<<"$out"; then echo "$out"; exit 1; fi
n=$(sed -n 's/^Overall number of objects *: *\([0-9]*\).*/\1/p' <<<"$out")
[[ "$n" == "$expected" ]] || { echo "$out"; echo "FAIL: read $n objects, expected $expected"; exit 1; }
grep -q "WHISKERS" <<<"$out" || { echo "FAIL: no WHISKERS sensor label seen"; exit 1; }
echo "ok: rawlog-edit read $n objects of $rawlog"
