#!/usr/bin/env bash
# check_manual.sh FORMSOLVE MANUAL: the checked-in parameter manual is what
# `formsolve --parameter-manual` writes now; else the difference and the
# command that brings it up to date.
set -euo pipefail
exe=$1 manual=$2
if ! diff -u "$manual" <("$exe" --parameter-manual); then
  echo "doc/parameters.md is out of date: build/formsolve --parameter-manual > doc/parameters.md"
  exit 1
fi
echo "doc/parameters.md is current"
