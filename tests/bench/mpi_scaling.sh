#!/usr/bin/env bash
# MPI strong and weak scaling of the distributed FE solver (fem/bodies/distributed_solver.h) through
# cases/tools/studies/fem_mpi: the flat punch at k = 0, degree 2, both linear solvers (MUMPS direct, CG + ML AMG).
#   strong: the same mesh (global refinements 1, 2, 3: 117k, 462k, 1.84M DoFs) on 1 and 2 processes;
#   weak:   about the same DoFs per process: np = 1 on the default near field against np = 2 on the
#           near field meshed at half the cell area (h_surface 0.125 a, h_far 1.5 a: 1.83x the DoFs);
#           levels 1, 2 (both solvers) and 3 (AMG only: 3.4M DoFs).
# Writes <out>/mpi_scaling.md and .csv (default reports/benchmarks), atomically (temporary names, then
# rename); a failed run leaves the previous report untouched.
#   tests/bench/mpi_scaling.sh [build-dir] [out-dir] [max-np] [levels]
# `./vv scaling` runs it. On a cluster node raise max-np (e.g. 4 8 16); every np from 1 to max-np in
# powers of two is run.
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:-$here/build}"
out="${2:-$here/reports/benchmarks}"
max_np="${3:-2}"
levels="${4:-1 2 3}"
exe="$build/cases/tools/studies/fem_mpi"
[ -x "$exe" ] || { echo "mpi_scaling: $exe not built (./vv build)" >&2; exit 2; }
command -v mpirun >/dev/null || { echo "mpi_scaling: mpirun not found (Debian: openmpi-bin)" >&2; exit 2; }
[[ "$max_np" =~ ^[1-9][0-9]*$ ]] || { echo "mpi_scaling: max-np = '$max_np' is not a positive integer" >&2; exit 2; }
# Open MPI refuses root unless told; harmless for other users and implementations.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export GRADCONTACT_MESH_CACHE="${GRADCONTACT_MESH_CACHE:-$build/mesh-cache}"
mkdir -p "$out"
tmp_csv="$out/.mpi_scaling.csv.tmp"
tmp_md="$out/.mpi_scaling.md.tmp"
trap 'rm -f "$tmp_csv" "$tmp_md"' EXIT
nps=""
for ((n = 1; n <= max_np; n *= 2)); do nps="$nps $n"; done

field() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<" $2"; }
echo "study,solver,np,level,dofs,dofs_per_process,setup_s,assemble_s,solver_setup_s,solve_s,total_s,iterations,peak_mb_max,peak_mb_sum,force" >"$tmp_csv"
run() { # study solver np level extra-args...
  local study=$1 solver=$2 np=$3 level=$4; shift 4
  local line
  line=$(mpirun -np "$np" "$exe" load=punch k=0 p=2 global="$level" solver="$solver" "$@" | grep '^load=') ||
    { echo "mpi_scaling: fem_mpi failed (np=$np level=$level solver=$solver $*)" >&2; exit 1; }
  local dofs; dofs=$(field dofs "$line")
  echo "$study,$solver,$np,$level,$dofs,$((dofs / np)),$(field setup "$line"),$(field assemble "$line"),$(field factorize "$line"),$(field solve "$line"),$(field total "$line"),$(field iterations "$line"),$(field peak_mb_max "$line"),$(field peak_mb_sum "$line"),$(field force "$line")" >>"$tmp_csv"
  echo "  $study $solver np=$np level=$level: $dofs DoFs, $(field total "$line") s" >&2
}
for solver in direct amg; do
  for level in $levels; do
    for np in $nps; do run strong "$solver" "$np" "$level"; done
  done
  for level in $levels; do
    # The weak pair at level 3 has millions of DoFs on np = 2: AMG's memory grows like the DoFs, but MUMPS's
    # fill grows faster and outgrows the memory of one node (peak_mb_max of the strong runs shows it): AMG only.
    [ "$level" -ge 3 ] && [ "$solver" = direct ] && continue
    run weak "$solver" 1 "$level"
    [ "$max_np" -ge 2 ] && run weak "$solver" 2 "$level" h_surface=0.125 h_far=1.5
  done
done

{
  echo "# MPI scaling of the distributed FE solver"
  echo
  echo "Flat punch, k = 0, nu = 0.3, degree 2, p4est + Trilinos (\`fem/bodies/distributed_solver.h\`), run by"
  echo "\`tests/bench/mpi_scaling.sh\` (\`./vv scaling\`). Machine: $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo),"
  echo "$(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1), load average before the run: $(cut -d' ' -f1-3 /proc/loadavg)."
  echo "$(mpirun --version 2>&1 | head -1); $(date -u '+%Y-%m-%d %H:%M UTC')."
  echo
  echo "Speed-up = T(np = 1) / T(np) on the same mesh (strong); efficiency = T(np = 1) / T(np) at about the"
  echo "same DoFs per process (weak). Times in s from the solver's own timers (max over processes);"
  echo "'solver setup' is the MUMPS factorisation or the ML AMG hierarchy; peak memory is VmHWM."
  echo
  echo "| study | solver | np | DoFs | DoFs / process | setup | assembly | solver setup | solve | total | speed-up / efficiency | CG iterations | peak MB (largest process / all) | force vs np = 1 |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
  awk -F, 'NR > 1 {
      key = $1 "," $2 "," $4
      if ($3 == 1) { t1[key] = $11; f1[key] = $15 }
      ratio = (key in t1) ? sprintf("%.2f", t1[key] / $11) : "-"
      df = (key in f1 && f1[key] != 0) ? sprintf("%.1e", ($15 - f1[key]) / f1[key]) : "-"
      if ($3 == 1) df = "-"
      printf "| %s | %s | %s | %d | %d | %s | %s | %s | %s | %s | %s | %s | %s / %s | %s |\n", $1, $2, $3, $5, $6, $7, $8, $9, $10, $11, ratio, $12, $13, $14, ($1 == "weak" ? "(other mesh)" : df)
    }' "$tmp_csv"
} >"$tmp_md"
mv "$tmp_csv" "$out/mpi_scaling.csv"
mv "$tmp_md" "$out/mpi_scaling.md"
trap - EXIT
echo "mpi_scaling: wrote $out/mpi_scaling.md" >&2
