#!/usr/bin/env bash
# Applies .clang-format to every C++ source; with --check, only reports.
set -euo pipefail
cd "$(dirname "$0")/.."
files=$(git ls-files '*.cc' '*.h')
if [ "${1:-}" = "--check" ]; then
  bad=0
  for f in $files; do clang-format --dry-run --Werror "$f" > /dev/null 2>&1 || { echo "not formatted: $f"; bad=1; }; done
  exit $bad
fi
clang-format -i $files
