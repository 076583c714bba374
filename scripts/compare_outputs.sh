#!/usr/bin/env bash
# Old-versus-new output comparison (docs/testing.md, "Comparing two builds"): runs two `linkproof`
# binaries over every bundled input and says, per command, whether what they print and write is
# the same once the parts that legitimately differ from run to run are masked.
#
#   scripts/compare_outputs.sh OLD_BINARY NEW_BINARY [OUTDIR]
#
# The commands (add_commands below): `check` (text and --json) of every scene under
# verify/scenes/; --arith double and mp50 of every polygon scene; `curvature` of every mechanism
# scene; `report` of every scene and claim file in md, tex and html (one directory per format);
# `prove`, `check-claim` and `report` of verify/claims/*.yaml at n = 5; `count`; a small `sweep`
# with a fixed seed (stdout, --out file, and two shards merged); `check-data` of the bundled CSVs;
# a small `bench --json`; --version, every --help, and a few bad inputs (exit 2). Each command
# runs in an empty working directory of its own (files it writes are compared too), under
# `setarch -R` (see "GiNaC" below), with a time limit of LINKPROOF_COMPARE_TIMEOUT seconds
# (default 120; a timeout shows as exit code 124).
#
# Masked (mask_filter below), in stdout, stderr and every written file alike, before comparing:
#   * run times: JSON members named *seconds*, *_ns*, *ns_*, and bench's cost_ratio,
#     fraction_within_2x and on_front (derived from timings); "0.12 s", "12 ms", "3 µs" in text;
#     table columns headed seconds, ms, time (ms), ... in Markdown, LaTeX, HTML and count's table;
#   * GiNaC tree sizes (tree_size, "tree N,", the "tree size" column): they count the terms of an
#     expression in whatever form it was built, which depends on GiNaC's term order;
#   * the git commit a binary was built from (report's reproduce table: 12 hex digits, maybe
#     "+modified"), which differs between any two builds;
#   * OUTDIR and temporary paths (/tmp/...).
# Exit codes are compared unmasked.
#
# GiNaC: the term order of a printed expression depends on GiNaC's hash values, which are seeded
# with the addresses of type information: they change with address randomisation (setarch -R
# turns it off, so one binary repeats itself) and between two builds (the addresses move). So
# when masked outputs differ, compare_outputs_equiv.py asks whether they differ only in the form
# of printed expressions: every differing line must pair with a differing line of the other side
# whose text outside its expressions is the same and whose expressions have the same values at
# two pseudo-random rational points (conditions `p = 0` up to sign). Such a command is
# "equivalent" (needs python3; without it, a difference).
#
# Prints one line per command, identical / equivalent / DIFFERS (with what differs and the start
# of the masked unified diff), and a summary. OUTDIR keeps old/ and new/ (raw outputs: per
# command .out, .err, .rc and the files in work/<id>/), masked/ (the masked copies of what
# differed) and diffs/<id>.diff. Exit 0 iff no command differs (with LINKPROOF_COMPARE_STRICT=1:
# iff every command is identical), 1 otherwise, 2 on bad usage. LINKPROOF_COMPARE_ONLY=1 compares
# the outputs already in OUTDIR again without running anything (after editing the masks).
# Run time on the shared 2-core development machine: 2.5 to 3.5 minutes for both binaries.
set -uo pipefail

usage() {
  echo "usage: $0 OLD_BINARY NEW_BINARY [OUTDIR]" >&2
  exit 2
}
[[ $# -eq 2 || $# -eq 3 ]] || usage
for b in "$1" "$2"; do
  [[ -x "$b" && -f "$b" ]] || { echo "compare_outputs: $b is not an executable file" >&2; exit 2; }
done
old_bin="$(realpath "$1")"
new_bin="$(realpath "$2")"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [[ $# -eq 3 ]]; then
  out="$3"
  # Never delete what this script did not write: an existing OUTDIR must be empty or be ours.
  if [[ -e "$out" && -n "$(ls -A "$out" 2>/dev/null)" && ! -f "$out/.compare_outputs" ]]; then
    echo "compare_outputs: $out exists, is not empty and was not written by this script" >&2
    exit 2
  fi
  mkdir -p "$out"
else
  out="$(mktemp -d "${TMPDIR:-/tmp}/linkproof-compare.XXXXXX")"
fi
out="$(cd "$out" && pwd)"
touch "$out/.compare_outputs"
timeout_s="${LINKPROOF_COMPARE_TIMEOUT:-120}"

# No address randomisation if the kernel lets us turn it off (containers may not).
no_aslr="setarch $(uname -m) -R"
if ! $no_aslr true 2>/dev/null; then
  echo "compare_outputs: warning: setarch -R is not available: printed GiNaC expressions (prove," \
       "check-claim, reports) change form from run to run; compare_outputs_equiv.py must judge them" >&2
  no_aslr=""
fi

# ---------------------------------------------------------------------------------------------
# The commands: `add ID SNIPPET`. A snippet is bash, run in an empty directory, where `lp` is the
# binary under test and $ROOT the repository; what it writes there is compared.
ids=()
declare -A snippet
add() {
  ids+=("$1")
  snippet[$1]="$2"
}

# shellcheck disable=SC2016  # $ROOT in single quotes: snippets are expanded where they run
add_commands() {
  local s name rel f fmt a
  add version 'lp --version'
  add help 'lp --help'
  for s in check sweep prove check-claim count bench curvature merge check-data report; do
    add "help.$s" "lp $s --help"
  done

  # Scenes: every *.yaml under verify/scenes, polygon or mechanism by its top-level key.
  while IFS= read -r f; do
    rel="${f#"$root"/verify/scenes/}"
    name="${rel%.yaml}"
    name="${name//\//.}"
    add "check.$name.text" "lp check \"\$ROOT/verify/scenes/$rel\""
    add "check.$name.json" "lp check \"\$ROOT/verify/scenes/$rel\" --json"
    if grep -q '^mechanism:' "$f"; then
      add "curvature.$name.text" "lp curvature \"\$ROOT/verify/scenes/$rel\""
      add "curvature.$name.json" "lp curvature \"\$ROOT/verify/scenes/$rel\" --json"
    else
      for a in double mp50; do
        add "check.$name.$a.text" "lp check \"\$ROOT/verify/scenes/$rel\" --arith $a"
        add "check.$name.$a.json" "lp check \"\$ROOT/verify/scenes/$rel\" --arith $a --json"
      done
    fi
    for fmt in md tex html; do
      add "report.$name.$fmt" "lp report \"\$ROOT/verify/scenes/$rel\" --format $fmt --out $fmt"
    done
  done < <(find "$root/verify/scenes" -name '*.yaml' | LC_ALL=C sort)
  add check.pentagon.strict.no-terms 'lp check "$ROOT/verify/scenes/pentagon.yaml" --strict --no-terms'
  add report.pentagon.numerics 'lp report "$ROOT/verify/scenes/pentagon.yaml" --numerics --format md --out md'
  add report.fig5_eightbar.plans \
    'lp report "$ROOT/verify/scenes/mechanisms/fig5_eightbar.yaml" --plans --format md --out md'

  # Claim files. A fixed n (and a ladder budget no run reaches) keeps proofs independent of speed.
  for f in "$root"/verify/claims/*.yaml; do
    rel="${f#"$root"/}"
    name="$(basename "$f" .yaml)"
    add "prove.$name.text" "lp prove --file \"\$ROOT/$rel\" --n-max 5 --ladder-seconds 600"
    add "prove.$name.json" "lp prove --file \"\$ROOT/$rel\" --n-max 5 --ladder-seconds 600 --json"
    add "check-claim.$name.text" "lp check-claim \"\$ROOT/$rel\" --n 5 --ladder-seconds 600"
    add "check-claim.$name.json" "lp check-claim \"\$ROOT/$rel\" --n 5 --ladder-seconds 600 --json"
    add "check-claim.$name.scene.json" \
      "lp check-claim \"\$ROOT/$rel\" --scene \"\$ROOT/verify/scenes/pentagon.yaml\" --arith double --json"
    for fmt in md tex html; do
      add "report.claims.$name.$fmt" \
        "lp report \"\$ROOT/$rel\" --n 5 --ladder-seconds 600 --format $fmt --out $fmt"
    done
  done
  add check-claim.vocabulary 'lp check-claim --vocabulary'

  add count.n4-7.text 'lp count --n 4..7'
  add count.n4-7.json 'lp count --n 4..7 --json'
  add count.eightbar.text 'lp count --eightbar'
  add count.eightbar.json 'lp count --eightbar --json'

  local sweep='lp sweep --n 4..6 --count 6 --seed 7 --jobs 1'
  add sweep.text "$sweep"
  add sweep.json "$sweep --json"
  add sweep.double.json "$sweep --arith double --json"
  add sweep.out "$sweep --out cases.jsonl --scenes scenes"
  add sweep.shards.merge "$sweep --shard 1/2 --out s1.jsonl && $sweep --shard 2/2 --out s2.jsonl &&
    lp merge --out merged.jsonl s2.jsonl s1.jsonl --json"

  local d='$ROOT/verify/data' m='$ROOT/verify/scenes/mechanisms'
  for f in watt_i stephenson_iii_example_2; do
    for s in matlab pmks; do
      add "check-data.$f.$s.text" "lp check-data \"$m/pmks_${f}_0.yaml\" \"$d/pmks_${f}_$s.csv\""
      add "check-data.$f.$s.json" "lp check-data \"$m/pmks_${f}_0.yaml\" \"$d/pmks_${f}_$s.csv\" --json"
    done
  done

  add bench.json 'lp bench --families dead_centre,q_infinity --cases 1 --n 5 --time-budget-ms 0 --adaptive-cases 5 --quiet --json'

  # Bad input: exit 2 and the message.
  add bad.missing-scene 'lp check "$ROOT/verify/scenes/no_such_scene.yaml"'
  add bad.polygon-check-data 'lp check-data "$ROOT/verify/scenes/pentagon.yaml" "$ROOT/verify/data/pmks_watt_i_matlab.csv"'
  add bad.unknown-subcommand 'lp no-such-command'
  add bad.arith 'lp check "$ROOT/verify/scenes/pentagon.yaml" --arith mp7'
}

# ---------------------------------------------------------------------------------------------
# The mask, applied to both sides before comparing (never to the raw outputs kept in OUTDIR):
# sed for values that can be recognised on their own, then awk for the timing columns of tables.
mask_filter() {
  sed -E \
    -e 's/("[A-Za-z_]*(seconds|_ns|ns_)[A-Za-z_]*"|"cost_ratio"|"fraction_within_2x"|"on_front"|"tree_size") *: *([-+0-9.eE]+|true|false)/\1: <masked>/g' \
    -e 's/\b[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)? ?(s|ms|µs|us|ns)\b/<t> \3/g' \
    -e 's/\btree +[0-9]+,/tree <n>,/g' \
    -e 's/\b[0-9a-f]{12}(\+modified)?\b/<commit>/g' \
    -e "s#$out/(old|new)#<outdir>#g" \
    -e 's#/tmp/[A-Za-z0-9._/-]*#<tmp>#g' |
    awk "$mask_columns_awk"
}

# Table columns whose header is a run time ("seconds", "time (ms)", "ms", "µs", ...): every cell
# below such a header becomes <t>, in Markdown (| a | b |), LaTeX (a & b \\), HTML (one <tr> a
# line) and fixed-width text (`count`: the last column, headed "ms") tables.
# shellcheck disable=SC2016  # awk code, not shell
mask_columns_awk='
function is_volatile(h) {
  gsub(/<[^>]*>|\\textbf\{|\}|\\\\/, "", h); gsub(/^ +| +$/, "", h)
  return h ~ /^(seconds|s|ms|µs|us|ns|time|run time|wall time|tree size)$/ || h ~ /^time \((s|ms|µs|us|ns)\)$/ ||
         h ~ /(seconds|µs|ns) per /
}
function header(line, sep,    n, i, c, found) {  # marks the time columns of a header row; 1 if any
  n = split(line, c, sep); found = 0
  for (i in col) delete col[i]
  for (i = 1; i <= n; i++) if (is_volatile(c[i])) { col[i] = 1; found = 1 }
  return found
}
function row(line, sep,    n, i, c, o) {
  n = split(line, c, sep); o = c[1]
  for (i = 2; i <= n; i++) {
    if (i in col) sub(/[-+]?[0-9][0-9.eE+-]*/, "<t>", c[i])
    o = o sep c[i]
  }
  return o
}
{ line = $0; gsub(/\\\|/, "\001", line); gsub(/\\&/, "\002", line) }  # escaped | and & separate nothing
mode == "md" && line !~ /^\|/ { mode = "" }
mode == "tex" && line ~ /\\end\{(longtable|tabular)/ { mode = "" }
mode == "html" && line ~ /<\/tbody>|<\/table>/ { mode = "" }
mode == "text" && line ~ /^ *$/ { mode = "" }
mode == "md" && line !~ /^\|(-+\|)+$/ { line = row(line, "|") }
mode == "tex" && line ~ / & / { line = row(line, " & ") }
mode == "html" && line ~ /^<tr><td>/ { line = row(line, "<td>") }
mode == "text" { sub(/[0-9]+\.[0-9]+$/, "<t>", line) }
mode == "" && line ~ /^\|.*\|$/ && header(line, "|") { mode = "md" }
mode == "" && line ~ /\\textbf\{.* & / && header(line, " & ") { mode = "tex" }
mode == "" && line ~ /<th>/ && header(line, "<th>") { mode = "html" }
mode == "" && line ~ /^verdict .* (ms|s|seconds)$/ { mode = "text" }
{ gsub(/\001/, "\\|", line); gsub(/\002/, "\\\\\\&", line); print line }
'

# ---------------------------------------------------------------------------------------------
run_side() {  # run_side SIDE BINARY
  local side="$1" bin="$2" id dir
  mkdir -p "$out/$side/work"
  for id in "${ids[@]}"; do
    dir="$out/$side/work/$id"
    mkdir -p "$dir"
    (
      cd "$dir" || exit 3
      export ROOT="$root" LP_BIN="$bin" LP_PREFIX="$no_aslr"
      # shellcheck disable=SC2086,SC2317  # LP_PREFIX: a command and its arguments, or empty
      lp() { $LP_PREFIX "$LP_BIN" "$@"; }
      export -f lp
      timeout --kill-after=5 "$timeout_s" bash -c "${snippet[$id]}" </dev/null \
        >"$out/$side/$id.out" 2>"$out/$side/$id.err"
    )
    echo $? >"$out/$side/$id.rc"
  done
}

# compare_item ID LABEL OLD NEW: masks both files into masked/, appends their diff to
# diffs/ID.diff; returns 0 if the masked files are identical, 1 if they are equivalent (they differ
# only in the printed form of expressions, compare_outputs_equiv.py), 2 if they differ.
compare_item() {
  local id="$1" label="$2" mo="$out/masked/old/$1/$2" mn="$out/masked/new/$1/$2"
  cmp -s "$3" "$4" && return 0
  mkdir -p "$(dirname "$mo")" "$(dirname "$mn")"
  mask_filter <"$3" >"$mo"
  mask_filter <"$4" >"$mn"
  cmp -s "$mo" "$mn" && return 0
  diff -u --label "old $label" --label "new $label" "$mo" "$mn" >>"$out/diffs/$id.diff"
  if [[ -n "$python" ]] && "$python" "$root/scripts/compare_outputs_equiv.py" "$mo" "$mn" >/dev/null 2>&1; then
    echo "equivalent: $label" >>"$out/diffs/$id.diff"
    return 1
  fi
  return 2
}

# compare_id ID: prints "identical", "equivalent<TAB>what" or "differs<TAB>what"; writes diffs/ID.diff.
compare_id() {
  local id="$1" differs=() equivalent=() rel o n rc_old rc_new status
  : >"$out/diffs/$id.diff"
  rc_old="$(cat "$out/old/$id.rc")"
  rc_new="$(cat "$out/new/$id.rc")"
  if [[ "$rc_old" != "$rc_new" ]]; then
    differs+=("exit $rc_old -> $rc_new")
    printf 'exit code: old %s, new %s\n' "$rc_old" "$rc_new" >>"$out/diffs/$id.diff"
  fi
  for rel in stdout stderr; do
    compare_item "$id" "$rel" "$out/old/$id.${rel#std}" "$out/new/$id.${rel#std}"
    status=$?
    [[ $status -eq 1 ]] && equivalent+=("$rel")
    [[ $status -eq 2 ]] && differs+=("$rel")
  done
  while IFS= read -r rel; do
    o="$out/old/work/$id/$rel"
    n="$out/new/work/$id/$rel"
    if [[ ! -f "$o" ]]; then differs+=("$rel only in new"); echo "only in new: $rel" >>"$out/diffs/$id.diff"; continue; fi
    if [[ ! -f "$n" ]]; then differs+=("$rel only in old"); echo "only in old: $rel" >>"$out/diffs/$id.diff"; continue; fi
    compare_item "$id" "files/$rel" "$o" "$n"
    status=$?
    [[ $status -eq 1 ]] && equivalent+=("$rel")
    [[ $status -eq 2 ]] && differs+=("$rel")
  done < <( (cd "$out/old/work/$id" && find . -type f; cd "$out/new/work/$id" && find . -type f) | sed 's#^\./##' |
           LC_ALL=C sort -u)
  local IFS=,
  if [[ ${#differs[@]} -gt 0 ]]; then
    printf 'differs\t%s\n' "${differs[*]}"
  elif [[ ${#equivalent[@]} -gt 0 ]]; then
    printf 'equivalent\t%s\n' "${equivalent[*]}"
  else
    echo identical
  fi
}

python="$(command -v python3 || true)"
if [[ -z "$python" ]]; then
  echo "compare_outputs: warning: no python3: expressions printed in another form count as differences" >&2
fi
start=$SECONDS
add_commands
echo "==> compare_outputs: ${#ids[@]} commands; old $old_bin, new $new_bin; outputs in $out"
if [[ "${LINKPROOF_COMPARE_ONLY:-0}" != 1 ]]; then
  rm -rf "$out/old" "$out/new"
  run_side old "$old_bin"
  echo "==> compare_outputs: old binary ran in $((SECONDS - start)) s"
  mid=$SECONDS
  run_side new "$new_bin"
  echo "==> compare_outputs: new binary ran in $((SECONDS - mid)) s"
fi

rm -rf "$out/diffs" "$out/masked"
mkdir -p "$out/diffs"
n_identical=0
n_equivalent=0
differ=()
for id in "${ids[@]}"; do
  result="$(compare_id "$id")"
  case "$result" in
    identical)
      n_identical=$((n_identical + 1))
      printf 'identical   %-55s exit %s\n' "$id" "$(cat "$out/old/$id.rc")"
      rm -f "$out/diffs/$id.diff"
      ;;
    equivalent*)
      n_equivalent=$((n_equivalent + 1))
      printf 'equivalent  %-55s exit %s; expressions printed in another form: %s\n' "$id" \
        "$(cat "$out/old/$id.rc")" "${result#*$'\t'}"
      ;;
    *)
      differ+=("$id")
      printf 'DIFFERS     %-55s %s\n' "$id" "${result#*$'\t'}"
      head -n 40 "$out/diffs/$id.diff" | sed 's/^/    | /' | cut -c1-240
      if [[ $(wc -l <"$out/diffs/$id.diff") -gt 40 ]]; then echo "    | ... (full diff: $out/diffs/$id.diff)"; fi
      ;;
  esac
done
echo "==> compare_outputs: ${n_identical} identical, ${n_equivalent} equivalent, ${#differ[@]} differ, of" \
     "${#ids[@]} commands ($((SECONDS - start)) s); outputs and diffs in $out"
if [[ ${#differ[@]} -gt 0 ]]; then
  echo "==> compare_outputs: differ: ${differ[*]}"
  exit 1
fi
if [[ $n_equivalent -gt 0 && "${LINKPROOF_COMPARE_STRICT:-0}" == 1 ]]; then
  echo "==> compare_outputs: LINKPROOF_COMPARE_STRICT=1: equivalent outputs count as differences"
  exit 1
fi
exit 0
