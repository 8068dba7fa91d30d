#!/usr/bin/env bash
# check_docs.sh SRC BUILD - the commands of README.md, docs/guide.md and docs/library.md
# run as written.  Each file's fenced ```sh blocks run in order with `bash -e`, from a
# folder that looks like the top of a checkout (the source tree's files linked, BUILD as
# build/, out/ and the rest written there, not into the source tree); a ```c block is
# saved under the name the text gives just before it ("Save this as `NAME`").  The
# library is installed into a staging folder first, and pkg-config and the dynamic linker
# are pointed at it as an install into a system prefix would be found.  Lines that would
# install, clone or run the suites themselves (make, meson setup/install, sudo, git
# clone) are not run here: CI's .ci/install-check and `make check` are those.
# Prints TAP; exits 1 if a block failed.
set -u
src=$(cd "${1:?usage: check_docs.sh SRC BUILD}" && pwd)
build=$(cd "${2:?usage: check_docs.sh SRC BUILD}" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/delam-docs.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# the library, headers and delam.pc in a staging folder
DESTDIR="$tmp/stage" meson install -C "$build" --no-rebuild --quiet >"$tmp/install.log" 2>&1 ||
  { echo "Bail out! meson install into a staging folder failed"; cat "$tmp/install.log"; exit 1; }
pc=$(find "$tmp/stage" -name delam.pc | head -1)
lib=$(dirname "$(find "$tmp/stage" -name 'libdelam.so*' | head -1)")
export PKG_CONFIG_PATH=$(dirname "$pc") PKG_CONFIG_SYSROOT_DIR="$tmp/stage" LD_LIBRARY_PATH="$lib"
export OMP_WAIT_POLICY=passive

n=0 fail=0
skip='^[[:space:]]*(make|meson setup|meson install|sudo|git clone)([[:space:]]|$)'
for doc in README.md docs/guide.md docs/library.md; do
  work="$tmp/work-${doc//\//-}"
  mkdir -p "$work"
  for f in Makefile README.md analytic data docs examples kernel meson.build meson_options.txt reports verify; do
    [ -e "$src/$f" ] && ln -s "$src/$f" "$work/$f"
  done
  ln -s "$build" "$work/build"
  # split the file into its blocks: NN.sh for sh, the named file for c
  awk -v dir="$work" '
    /Save this as `[^`]+`/ { match($0, /Save this as `[^`]+`/); name = substr($0, RSTART + 14, RLENGTH - 15) }
    /^```sh[[:space:]]*$/ { k++; out = sprintf("%s/.block-%02d.sh", dir, k); inb = 1; next }
    /^```c[[:space:]]*$/  { out = dir "/" (name != "" ? name : "unnamed.c"); inb = 1; next }
    /^```/ { if (inb) { close(out); inb = 0 } next }
    inb { print > out }' "$src/$doc"
  for b in "$work"/.block-*.sh; do
    [ -e "$b" ] || continue
    n=$((n + 1))
    grep -vE "$skip" "$b" >"$b.run"
    if (cd "$work" && bash -e "$b.run") >"$b.log" 2>&1; then
      echo "ok $n - $doc block $(basename "$b" .sh | sed 's/.block-//')"
    else
      fail=$((fail + 1))
      echo "not ok $n - $doc block $(basename "$b" .sh | sed 's/.block-//')"
      sed 's/^/#   /' "$b.run"
      tail -20 "$b.log" | sed 's/^/#   output: /'
    fi
  done
done
echo "1..$n"
[ "$fail" = 0 ]
