#!/usr/bin/env bash
# Fails when a C++ file of the project differs from .clang-format (fix: clang-format -i FILE).
# find, not git ls-files: CI's fresh root gets the sources without .git.
set -euo pipefail
cd "$(dirname "$0")/.."
find core report ui app tests bench fuzz packaging -name build -prune -o \( -name '*.cpp' -o -name '*.h' \) -print0 |
    xargs -0 clang-format --dry-run --Werror
