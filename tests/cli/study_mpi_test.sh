#!/usr/bin/env bash
# `mpirun -n 2 ancfnet study` on this machine (loopback) writes the same table as the study run
# with -j 2 without MPI: rank 0 hands the cases of tests/cli/study/grid.yaml to rank 1. Skipped
# (exit 77) when ancfnet was built without MPI or mpirun is missing (scripts/install-deps.sh
# installs Debian's OpenMPI).
# Usage: bash tests/cli/study_mpi_test.sh <ancfnet binary> <repo root>
set -euo pipefail

ancfnet="${1:?usage: study_mpi_test.sh <ancfnet binary> <repo root>}"
root="${2:?usage: study_mpi_test.sh <ancfnet binary> <repo root>}"
if ! "$ancfnet" study --help | grep -q "MPI support: yes"; then
  echo "SKIP: ancfnet was built without MPI (install libopenmpi-dev and configure again)"
  exit 77
fi
if ! command -v mpirun >/dev/null; then
  echo "SKIP: no mpirun (install openmpi-bin)"
  exit 77
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1
# OpenMPI refuses root unless told; one machine, two ranks over loopback.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl=self,tcp OMPI_MCA_btl_tcp_if_include=lo OMPI_MCA_oob_tcp_if_include=lo

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

study="$root/tests/cli/study/grid.yaml"
"$ancfnet" study "$study" -o "$work/local" -j 2 2>"$work/local.stderr" ||
  fail "local: exit $?: $(cat "$work/local.stderr")"
timeout 120 mpirun --oversubscribe -n 2 "$ancfnet" study "$study" -o "$work/mpi" \
  >"$work/mpi.stdout" 2>"$work/mpi.stderr" || fail "mpirun: exit $?: $(cat "$work/mpi.stderr")"
grep -q "study: 4 cases, 0 done before, 4 to run on 1 MPI ranks" "$work/mpi.stderr" ||
  fail "mpirun: not handed out to the ranks: $(cat "$work/mpi.stderr")"
cmp "$work/local/study.csv" "$work/mpi/study.csv" || fail "the tables differ"
echo "study under mpirun: OK"
