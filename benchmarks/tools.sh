#!/usr/bin/env bash
# Every figure of doc/tools.md: the contact search against the facet count
# (tool_search.sh, section 1) and the square cup (square_cup.sh, section 2).
# The square cup takes about 70 min on 2 cores; the tables go to stdout, the
# runs to results/.
#   bash benchmarks/tools.sh
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
echo "## 1. Meshed copies of the default cup's tools"
bash "$here/tool_search.sh"
echo
echo "## 2. The square cup"
bash "$here/square_cup.sh"
