#!/usr/bin/env bash
# scripts/build_at.sh without a build: a commit resolves to its cache folder, a binary already
# there is reused (its path printed, nothing built), and a name that is no commit exits 2.
set -euo pipefail
root="$1"
cache="$(mktemp -d)"
trap 'rm -rf "$cache"' EXIT
head="$(git -C "$root" rev-parse HEAD)"
mkdir -p "$cache/${head:0:12}/build"
printf '#!/bin/sh\n' > "$cache/${head:0:12}/build/rayvec"
chmod +x "$cache/${head:0:12}/build/rayvec"
got="$("$root/scripts/build_at.sh" HEAD "$cache" 2>"$cache/err")"
[ "$got" = "$cache/${head:0:12}/build/rayvec" ] || { echo "HEAD gave '$got'"; exit 1; }
[ ! -e "$cache/${head:0:12}/src" ] || { echo "a cached binary was rebuilt"; exit 1; }
status=0
"$root/scripts/build_at.sh" no-such-commit "$cache" 2>"$cache/err" >/dev/null || status=$?
[ "$status" = 2 ] || { echo "a bad commit exited $status, not 2"; exit 1; }
grep -q "is not a commit" "$cache/err" || { echo "no message for a bad commit"; cat "$cache/err"; exit 1; }
echo "build_at.sh: resolves, reuses, rejects"
