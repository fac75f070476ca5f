#!/usr/bin/env bash
# Checks (or with --fix, applies) clang-format on every tracked or new C++ file.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files --cached --others --exclude-standard -- '*.cpp' '*.hpp' | sort -u)
((${#files[@]})) || { echo "check-format: no C++ files"; exit 0; }
if [[ "${1:-}" == "--fix" ]]; then
  clang-format -i "${files[@]}"
  exit 0
fi
bad=0
for f in "${files[@]}"; do
  [[ -f "$f" ]] || continue
  if ! clang-format --dry-run -Werror "$f" >/dev/null 2>&1; then
    echo "check-format: $f is not clang-formatted (run: make format)" >&2
    bad=1
  fi
done
((bad == 0)) && echo "check-format: ${#files[@]} files formatted"
exit $bad
