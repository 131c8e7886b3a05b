#!/usr/bin/env bash
# Fails when a tracked C++ file (*.hpp, *.cpp, *.h under include/, robust/,
# src/, fuzz/, bench/, tests/, tools/, bullet/, python/, examples/) differs
# from what clang-format-14 makes of it with the repository's .clang-format.
# Lists the files that differ; format them with
#   git ls-files -z 'include/*' 'robust/*' 'src/*' 'fuzz/*' 'bench/*' 'tests/*' \
#     'tools/*' 'bullet/*' 'python/*' 'examples/*' | grep -zE '\.(hpp|cpp|h)$' |
#     xargs -0 clang-format-14 -i
#
# Usage: bash .ci/check_format.sh   (exit 0 clean, 1 files differ,
#        77 no git checkout, 2 clang-format-14 missing)
set -euo pipefail
cd "$(dirname "$0")/.."
if ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  echo "check_format: not a git checkout, nothing to check" >&2
  exit 77
fi
fmt="${CLANG_FORMAT:-clang-format-14}"
if ! command -v "$fmt" >/dev/null 2>&1; then
  echo "check_format: $fmt not found (Debian package clang-format-14)" >&2
  exit 2
fi

mapfile -d '' files < <(git ls-files -z 'include/*' 'robust/*' 'src/*' 'fuzz/*' 'bench/*' 'tests/*' \
  'tools/*' 'bullet/*' 'python/*' 'examples/*' | grep -zE '\.(hpp|cpp|h)$')

# One clang-format run over every file; each difference is reported as
# "FILE:LINE:COL: error: code should be clang-formatted".
out=$("$fmt" --dry-run -Werror "${files[@]}" 2>&1) && status=0 || status=$?
mapfile -t bad < <(printf '%s\n' "$out" | grep -oP '^.+?(?=:[0-9]+:[0-9]+: error: )' | sort -u)
if [ "$status" != 0 ] && [ "${#bad[@]}" = 0 ]; then
  printf '%s\n' "$out" >&2
  echo "check_format: $fmt failed" >&2
  exit 2
fi

if [ "${#bad[@]}" != 0 ]; then
  printf '%s\n' "${bad[@]}"
  echo "check_format: the ${#bad[@]} files above differ from $fmt's format (.clang-format);" \
       "run $fmt -i on them" >&2
  exit 1
fi
echo "check_format: ${#files[@]} files follow .clang-format"
