#!/usr/bin/env bash
# The code checks CI runs before the tests (.ci/run); run them yourself before you land:
#   tools/check_code.sh            # all four checks over the tracked C++ sources
# Each check prints what it found and the script exits 1 if any failed. The tools come from
# tools/setup.sh (Debian: clang-format, cppcheck; PyPI into .venv: lizard). Thresholds and
# allowlists live here and in tools/check/; docs/architecture.md explains them.
set -uo pipefail
cd "$(dirname "$0")/.."

# Function ceiling (lizard): longer or more branched functions fail unless allowlisted, with a
# reason, in tools/check/long_functions.txt. Lower these as the allowlist empties.
MAX_FUNCTION_LINES=150
MAX_FUNCTION_CCN=35

LIZARD=lizard
[ -x .venv/bin/lizard ] && LIZARD=.venv/bin/lizard
failed=()
files() { git ls-files --cached --others --exclude-standard "$@"; }
mapfile -t SOURCES < <(files '*.cc' '*.h')
mapfile -t LIBRARY_SOURCES < <(files '*.cc' | grep -v -e '^tests/' -e '^python/src/')

echo "[check] clang-format (.clang-format) over ${#SOURCES[@]} files"
if ! clang-format --dry-run --Werror "${SOURCES[@]}"; then
  echo "[check] formatting: run  clang-format -i <file>  on the files above"
  failed+=(clang-format)
fi

echo "[check] function ceiling: length <= $MAX_FUNCTION_LINES lines, CCN <= $MAX_FUNCTION_CCN"
if ! "$LIZARD" -w -L "$MAX_FUNCTION_LINES" -C "$MAX_FUNCTION_CCN" -a 100 \
    -W tools/check/long_functions.txt "${SOURCES[@]}"; then
  echo "[check] split the functions above (or allowlist one, with its reason, in"
  echo "        tools/check/long_functions.txt)"
  failed+=(lizard)
fi

echo "[check] repeated code (lizard -Eduplicate)"
# (lizard's own exit code counts its default complexity warnings: only the report is read here)
duplicates="$("$LIZARD" -Eduplicate "${SOURCES[@]}" 2>&1)"
if ! python3 tools/check/duplicates.py tools/check/duplicates_allowed.txt <<<"$duplicates"; then
  failed+=(duplicates)
fi

# cppcheck's warning, performance and portability classes (not style): likely bugs, needless
# copies, non-portable code. Tests and the Python bindings are left out (their macros are not
# C++ cppcheck can parse without the GoogleTest and nanobind headers).
echo "[check] cppcheck (warning, performance, portability) over ${#LIBRARY_SOURCES[@]} files"
if ! cppcheck -q -j2 --std=c++17 --language=c++ --enable=warning,performance,portability \
    --inline-suppr --suppressions-list=tools/check/cppcheck_suppressions.txt \
    --error-exitcode=1 -I . "${LIBRARY_SOURCES[@]}"; then
  failed+=(cppcheck)
fi

# Python: ruff's lint and format (pyproject.toml [tool.ruff]; pinned in requirements.txt).
RUFF=ruff
[ -x .venv/bin/ruff ] && RUFF=.venv/bin/ruff
mapfile -t PY_SOURCES < <(files '*.py')
echo "[check] ruff lint and format over ${#PY_SOURCES[@]} Python files"
if ! "$RUFF" check -q "${PY_SOURCES[@]}"; then
  echo "[check] lint: fix the lines above (ruff check --fix helps)"
  failed+=(ruff-lint)
fi
if ! "$RUFF" format --check -q "${PY_SOURCES[@]}"; then
  echo "[check] formatting: run  .venv/bin/ruff format <file>  on the files above"
  failed+=(ruff-format)
fi

if ((${#failed[@]})); then
  echo "[check] FAILED: ${failed[*]}"
  exit 1
fi
echo "[check] all code checks passed"
