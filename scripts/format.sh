#!/usr/bin/env bash
# Formats hydrocoef's C++ code with the repository's .clang-format (clang-format 14, the Debian package
# clang-format, which scripts/install-deps.sh installs): every tracked C/C++ source and header under
# src/ importers/ cli/ tests/ bench/ include/ python/.
#   scripts/format.sh              formats them in place
#   scripts/format.sh --check      changes nothing: lists the files that differ from their formatting and
#                                  exits 1 when one does
#   scripts/format.sh [--check] FILE...   only these files
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
check=false
if [[ ${1:-} == --check ]]; then
  check=true
  shift
fi
if ! command -v clang-format >/dev/null 2>&1; then
  echo "format: clang-format is not installed (Debian package clang-format: bash scripts/install-deps.sh)" >&2
  exit 2
fi
files=("$@") # relative to the working directory
if ((${#files[@]} == 0)); then
  mapfile -t files < <(git -C "$root" ls-files -- src importers cli tests bench include python |
    grep -E '\.(c|cc|cpp|cxx|h|hh|hpp|hxx)$' | grep -v '^tests/data/' | sed "s|^|$root/|")
fi

if ! $check; then
  clang-format -i --style="file:$root/.clang-format" "${files[@]}"
  echo "format: ${#files[@]} files formatted with $(clang-format --version | sed 's/^.*version \([0-9.]*\).*$/clang-format \1/')"
  exit 0
fi
differ=()
for file in "${files[@]}"; do
  if ! clang-format --style="file:$root/.clang-format" --dry-run -Werror "$file" >/dev/null 2>&1; then differ+=("$file"); fi
done
if ((${#differ[@]} > 0)); then
  printf 'format: %s differs from .clang-format\n' "${differ[@]#"$root/"}"
  echo "format: ${#differ[@]} of ${#files[@]} files differ: run scripts/format.sh" >&2
  exit 1
fi
echo "format: the ${#files[@]} files are formatted with .clang-format"
