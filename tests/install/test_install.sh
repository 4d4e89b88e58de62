#!/usr/bin/env bash
# `cmake --install` into a fresh prefix, then use what it installed as others would: the CLI
# (--version), a CMake project (find_package(kinergy), tests/consumer), a plain compile with
# pkg-config, the man page and the bash completion.
#   bash tests/install/test_install.sh BUILD_DIR
# Expected value by hand (the scene's description): the sliding rod's omega2 = 3.50 rad/s.
set -euo pipefail
src="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(cd "$1" && pwd)"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
prefix="$tmp/prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
fail() { echo "test_install: $*" >&2; exit 1; }
for f in bin/kinergy include/kinergy/problem.hpp share/bash-completion/completions/kinergy; do
  [ -e "$prefix/$f" ] || fail "not installed: $f"
done
config=$(find "$prefix" -name kinergyConfig.cmake | head -1)
pc=$(find "$prefix" -name kinergy.pc | head -1)
[ -n "$config" ] || fail "no kinergyConfig.cmake"
[ -n "$pc" ] || fail "no kinergy.pc"
if command -v help2man >/dev/null; then
  [ -e "$prefix/share/man/man1/kinergy.1" ] || fail "no man page"
  grep -q '^\.SS simulate' "$prefix/share/man/man1/kinergy.1" || fail "the man page has no section for simulate"
  ! grep -q "$build" "$prefix/share/man/man1/kinergy.1" || fail "the man page names the build directory"
fi
# the CLI
[ "$("$prefix/bin/kinergy" --version)" = "kinergy 0.1.0" ] || fail "kinergy --version: $("$prefix/bin/kinergy" --version)"
# proven digits: the ball arithmetic module, found beside the installed CLI (<prefix>/LIBDIR/kinergy)
arb=$(find "$prefix" -name kinergy_arb.so | head -1)
[ -n "$arb" ] || fail "no kinergy_arb.so installed"
out=$(LD_DEBUG=files "$prefix/bin/kinergy" solve "$src/derivations/energy/sliding_rod.yaml" --digits 20 2>&1)
grep -q '= 3.5017852589786256052 rad/s   (proven: ball radius' <<<"$out" || fail "--digits 20 with the installed CLI printed: $out"
grep -q "file=$arb " <<<"$out" || grep -q "file=$(cd "$(dirname "$arb")" && pwd -P)/kinergy_arb.so " <<<"$out" ||
  fail "the installed CLI did not load its own module $arb: $(grep -o 'file=[^ ]*kinergy_arb.so' <<<"$out")"
# the same when it is started by its bare name, found on PATH
out=$(cd "$tmp" && PATH="$prefix/bin:$PATH" LD_DEBUG=files kinergy solve "$src/derivations/energy/sliding_rod.yaml" --digits 20 2>&1)
grep -q '(proven: ball radius' <<<"$out" || fail "kinergy on PATH, --digits 20, printed: $out"
grep -q "file=$arb " <<<"$out" || grep -q "file=$(cd "$(dirname "$arb")" && pwd -P)/kinergy_arb.so " <<<"$out" ||
  fail "kinergy on PATH did not load its own module $arb: $(grep -o 'file=[^ ]*kinergy_arb.so' <<<"$out")"
check_omega() {  # the consumer's output: omega2 = … = 3.50… (to the scene's three figures)
  grep -E '^omega2 = .* = 3\.50[0-9]*$' <<<"$1" >/dev/null || fail "$2 printed: $1"
}
# a CMake project
cmake -S "$src/tests/consumer" -B "$tmp/consumer" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$tmp/consumer" >/dev/null
out=$("$tmp/consumer/consumer" "$src/derivations/energy/sliding_rod.yaml")
check_omega "$out" "the CMake consumer"
# pkg-config
flags=$(PKG_CONFIG_PATH="$(dirname "$pc")" pkg-config --cflags --libs kinergy)
c++ -O1 -o "$tmp/pc_consumer" "$src/tests/consumer/main.cpp" $flags
out=$("$tmp/pc_consumer" "$src/derivations/energy/sliding_rod.yaml")
check_omega "$out" "the pkg-config consumer"
# bash completion: subcommands, then a subcommand's options (read from its --help)
completion="$prefix/share/bash-completion/completions/kinergy"
got=$(bash -c "source '$completion'; COMP_WORDS=('$prefix/bin/kinergy' dr); COMP_CWORD=1; _kinergy; echo \"\${COMPREPLY[*]}\"")
[ "$got" = "draw" ] || fail "completing 'kinergy dr' gave '$got'"
got=$(bash -c "source '$completion'; COMP_WORDS=('$prefix/bin/kinergy' simulate --ani); COMP_CWORD=2; _kinergy; echo \"\${COMPREPLY[*]}\"")
[ "$got" = "--animate" ] || fail "completing 'kinergy simulate --ani' gave '$got'"
got=$(bash -c "source '$completion'; COMP_WORDS=('$prefix/bin/kinergy' simulate x.yaml --method s); COMP_CWORD=4; _kinergy; echo \"\${COMPREPLY[*]}\"")
[ "$got" = "symplectic" ] || fail "completing '--method s' gave '$got'"
# the Python package, where it was built: importable from the prefix, its worked problems and its
# ball arithmetic module installed inside it
module=$(find "$prefix" -name '_kinergy.cpython-*.so' | head -1)
if [ -e "$build/python" ]; then
  [ -n "$module" ] || fail "the Python package is not installed"
  pkgpath="$(dirname "$(dirname "$module")")"
  got=$(cd / && PYTHONPATH="$pkgpath" /usr/bin/python3 -c "import kinergy; print(float(kinergy.example('energy/sliding_rod').solve()['omega2']))")
  grep -E '^3\.50' <<<"$got" >/dev/null || fail "the installed Python package printed: $got"
  # its proven digits, from the module installed beside its core
  got=$(cd / && LD_DEBUG=files PYTHONPATH="$pkgpath" /usr/bin/python3 -c "import kinergy; print(kinergy.example('energy/sliding_rod').solve()['omega2'].ball(20))" 2>&1)
  grep -q "'proven': True" <<<"$got" || fail "the installed Python package's ball(20): $got"
  grep -q "file=$(dirname "$module")/kinergy_arb.so " <<<"$got" ||
    fail "the installed Python package did not load the module installed beside its core: $(grep -o 'file=[^ ]*kinergy_arb.so' <<<"$got")"
fi
echo "test_install: installed, found by CMake and pkg-config, man page, completion and the Python package work"
