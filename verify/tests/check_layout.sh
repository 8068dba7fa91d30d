#!/usr/bin/env bash
# check_layout.sh SRC - the bounds of the code's layout:
#   public-header    kernel/mpm.h, the installed contract, is at most 250 lines;
#   private-headers  verify/, analytic/, examples/ and fuzz/ include no kernel header but mpm.h
#                    (struct mpm_sim is theirs to read only through its calls);
#   include-circle   no header of kernel/, analytic/ or verify/ includes itself through others;
#   function-length  no function of kernel/, analytic/ or verify/ is over 100 lines (from
#                    the line naming it to its closing brace at column 0);
#   static-control   the static solver's path control in kernel/mpm_static_path.c, its
#                    mpm_static_step not recursive, none of it in kernel/mpm_static.c;
#   verify-files     no file of verify/ is over 600 lines;
#   file-headers     no C file of kernel/, analytic/ or verify/ (or their tests/) opens with
#                    a comment of over 15 lines (check_headers.py).
# Prints TAP; exits 1 if a check failed.
set -u
src=${1:?usage: check_layout.sh SRC}
cd "$src" || exit 1
n=0 fail=0
result() { # result ID WHY (empty WHY: pass)
  n=$((n + 1))
  if [ -z "$2" ]; then echo "ok $n - $1"; else fail=$((fail + 1)); echo "not ok $n - $1: $2"; fi
}

lines=$(wc -l <kernel/mpm.h)
result public-header "$([ "$lines" -le 250 ] || echo "kernel/mpm.h has $lines lines")"

private=$(ls kernel/*.h | xargs -n1 basename | grep -vx 'mpm.h' | sed 's/\./\\./g' | paste -sd'|')
bad=$(grep -lE "#include [\"<](delam/)?($private)[\">]" verify/*.[ch] verify/tests/*.c analytic/*.[ch] \
  analytic/tests/*.c examples/*.c fuzz/*.c 2>/dev/null | paste -sd' ')
result private-headers "$([ -z "$bad" ] || echo "a private kernel header included by $bad")"

python3 - <<'PY' >"${TMPDIR:-/tmp}/delam-layout.$$" 2>&1
import glob, os, re
heads = {os.path.basename(f): re.findall(r'#include "([^"]+)"', open(f).read())
         for d in ("kernel", "analytic", "verify") for f in glob.glob(d + "/*.h")}
state, circles = {}, []
def walk(h, path):
    state[h] = 1
    for i in heads.get(h, []):
        if i in heads and state.get(i) == 1:
            circles.append(" -> ".join(path[path.index(i):] + [i]))
        elif i in heads and not state.get(i):
            walk(i, path + [i])
    state[h] = 2
for h in sorted(heads):
    if not state.get(h):
        walk(h, [h])
print("CIRCLES", "; ".join(circles))
long = []
for f in sorted(glob.glob("kernel/*.[ch]") + glob.glob("analytic/*.[ch]") + glob.glob("verify/*.[ch]")):
    L, start = open(f).read().split("\n"), None
    for i, l in enumerate(L):
        if start is None and l.startswith("{") and i > 0:
            j = i - 1
            while j >= 0 and not re.match(r"^[A-Za-z_].*\(", L[j]):
                j -= 1
            start = j
        elif start is not None and l.startswith("}"):
            if i - start + 1 > 100:
                names = [w for w in re.findall(r"(\w+)\s*\(", L[start]) if not w.startswith("__")]
                long.append("%s %s %d" % (f, names[0] if names else "?", i - start + 1))
            start = None
print("LONG", ", ".join(long))
PY
out=$(cat "${TMPDIR:-/tmp}/delam-layout.$$"); rm -f "${TMPDIR:-/tmp}/delam-layout.$$"
circ=$(sed -n 's/^CIRCLES //p' <<<"$out")
result include-circle "$([ -z "$circ" ] && grep -q '^CIRCLES' <<<"$out" || echo "${circ:-$out}")"
long=$(sed -n 's/^LONG //p' <<<"$out")
result function-length "$([ -z "$long" ] && grep -q '^LONG' <<<"$out" || echo "over 100 lines: ${long:-$out}")"

# the static solver's path control is its own module: kernel/mpm_static_path.c holds
# mpm_static_step, which does not call itself, and kernel/mpm_static.c (Newton) none of the
# control's functions
ctl=""
grep -q '^mpm_status mpm_static_step(' kernel/mpm_static_path.c 2>/dev/null || ctl="mpm_static_step is not in kernel/mpm_static_path.c"
rec=$(awk '/^mpm_status mpm_static_step\(/ { f = 1; next } f && /^}/ { f = 0 } f && /mpm_static_step\(/ { print FILENAME ":" FNR }' kernel/*.c)
[ -z "$rec" ] || ctl="$ctl; mpm_static_step calls itself at $rec"
in_newton=$(grep -nE '^static [a-z_ ]+\b(set_mode|resume|let_go|pin|shrink|next_step|path_sound|turns|stalls)\(' kernel/mpm_static.c | paste -sd' ')
[ -z "$in_newton" ] || ctl="$ctl; path control in kernel/mpm_static.c: $in_newton"
result static-control "${ctl#; }"

big=$(wc -l verify/*.[ch] | awk '$2 != "total" && $1 > 600 {printf "%s %s ", $2, $1}')
result verify-files "$([ -z "$big" ] || echo "over 600 lines: $big")"

heads=$(python3 verify/tests/check_headers.py . 15 2>&1 | paste -sd' ')
result file-headers "$([ -z "$heads" ] || echo "headers over 15 lines: $heads")"

echo "1..$n"
[ "$fail" -eq 0 ]
