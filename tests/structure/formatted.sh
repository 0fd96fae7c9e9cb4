#!/usr/bin/env bash
# Checks that every C++ file of src/, shaders/ and tests/ is formatted as .clang-format says
# (clang-format --dry-run reports nothing). Exit 77 (skipped) when clang-format is not installed;
# scripts/install-deps.sh installs it.
# Usage: formatted.sh REPOSITORY_ROOT
set -euo pipefail
root="$1"
format=$(command -v clang-format || command -v clang-format-14 || true)
if [[ -z "$format" ]]; then
  echo "SKIP: clang-format not found"
  exit 77
fi
cd "$root"
mapfile -t files < <(find src shaders tests -type f \( -name '*.h' -o -name '*.cpp' -o -name '*.inl' -o -name '*.cu' -o -name '*.cuh' \) | sort)
if ((${#files[@]} == 0)); then echo "FAIL: no sources found under $root"; exit 1; fi
if ! "$format" --dry-run --Werror "${files[@]}"; then
  echo "FAIL: run: clang-format -i \$(git ls-files 'src/*' 'shaders/*' 'tests/*' | grep -E '\\.(h|cpp|inl|cu|cuh)\$')"
  exit 1
fi
echo "checked ${#files[@]} files with $("$format" --version)"
