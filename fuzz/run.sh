#!/usr/bin/env bash
# Fuzzes the parsers with libFuzzer (libfuzzer-sys), on stable Rust.
#
#   fuzz/run.sh TARGET|all SECONDS [libFuzzer options…]   e.g. fuzz/run.sh scene 15
#   fuzz/run.sh TARGET|all --runs N [libFuzzer options…]  e.g. fuzz/run.sh obj --runs 10000000
#
# Targets: scene (scene TOML), obj (OBJ meshes), script (the GL-call script reader),
# cli_values (the command line's value parsers). `all` runs them one after another.
#
# The targets are built with SanitizerCoverage (`-Cpasses=sancov-module` and its LLVM
# options, all accepted by stable rustc) and no sanitizer, for the host triple so that build
# scripts and proc macros stay uninstrumented — what `cargo fuzz build -s none` does, with
# nothing to install: libfuzzer-sys compiles libFuzzer with the system's C++ compiler.
# Release with debug assertions and overflow checks (fuzz/Cargo.toml).
#
# The corpus grows in fuzz/corpus/TARGET (not checked in), seeded from assets/ (scene TOMLs,
# OBJ files), tests/scripts/ and fuzz/seeds/TARGET. A crash, a panic, a timeout (a hang:
# -timeout=5 s per input) or running out of memory (-rss_limit_mb=2048) writes the input to
# fuzz/artifacts/TARGET/ and makes the script fail; replay one with
#   fuzz/target/<host>/release/TARGET fuzz/artifacts/TARGET/crash-…
set -euo pipefail
cd "$(dirname "$0")"

all=(scene obj script cli_values)
[ $# -ge 2 ] || { sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
which=$1
shift
if [ "$1" = "--runs" ]; then
  limit=("-runs=$2")
  shift 2
else
  limit=("-max_total_time=$1")
  shift
fi
case "$which" in
  all) targets=("${all[@]}") ;;
  scene | obj | script | cli_values) targets=("$which") ;;
  *) echo "unknown target $which (known: ${all[*]} all)" >&2; exit 2 ;;
esac

host=$(rustc -vV | sed -n 's/^host: //p')
export RUSTFLAGS="--cfg fuzzing -Cpasses=sancov-module \
  -Cllvm-args=-sanitizer-coverage-level=4 \
  -Cllvm-args=-sanitizer-coverage-inline-8bit-counters \
  -Cllvm-args=-sanitizer-coverage-pc-table \
  -Cllvm-args=-sanitizer-coverage-trace-compares"
# Not --locked: fuzz/Cargo.lock pins what it lists, and a dependency the main crate gained
# since is resolved rather than failing the build.
cargo build --release --target "$host" --bins

for target in "${targets[@]}"; do
  case "$target" in
    scene) seeds=(../assets seeds/scene) max_len=8192 ;;
    obj) seeds=(../assets seeds/obj) max_len=8192 ;;
    script) seeds=(../tests/scripts seeds/script) max_len=4096 ;;
    cli_values) seeds=(seeds/cli_values) max_len=64 ;;
  esac
  dirs=()
  for d in "${seeds[@]}"; do [ -d "$d" ] && dirs+=("$d"); done
  mkdir -p "corpus/$target" "artifacts/$target"
  echo "== fuzzing $target (${limit[*]})"
  "target/$host/release/$target" "corpus/$target" "${dirs[@]}" \
    -artifact_prefix="artifacts/$target/" -timeout=5 -rss_limit_mb=2048 \
    -max_len="$max_len" -print_final_stats=1 "${limit[@]}" "$@"
done
