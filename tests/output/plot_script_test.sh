#!/usr/bin/env bash
# plot_script_test.sh MAKE_SAMPLE_RUN PLOT WORKDIR: scripts/plot on a full run, a run
# without bodies, and bad input.
set -euo pipefail
make_sample_run=$1 plot=$2 work=$3
rm -rf "$work"
mkdir -p "$work/out"

"$make_sample_run" "$work/run.h5"
"$plot" "$work/run.h5"
for kind in trajectories velocities forces coupling; do
  test -s "$work/run-$kind.png" || { echo "missing run-$kind.png"; exit 1; }
done

"$make_sample_run" "$work/empty.h5" --no-bodies
"$plot" "$work/empty.h5" --out "$work/out"
test -s "$work/out/empty-coupling.png"
test ! -e "$work/out/empty-trajectories.png"

status=0
"$plot" "$work/missing.h5" 2>"$work/err" || status=$?
[ "$status" = 2 ] && [ "$(wc -l <"$work/err")" = 1 ] || { echo "missing file: exit $status"; exit 1; }
echo "not hdf5" >"$work/text.h5"
status=0
"$plot" "$work/text.h5" 2>"$work/err" || status=$?
[ "$status" = 2 ] && [ "$(wc -l <"$work/err")" = 1 ] || { echo "text file: exit $status"; exit 1; }
/usr/bin/python3 -c "import h5py, sys; h5py.File(sys.argv[1], 'w')['x'] = [1]" "$work/other.h5"
status=0
"$plot" "$work/other.h5" 2>"$work/err" || status=$?
[ "$status" = 2 ] && [ "$(wc -l <"$work/err")" = 1 ] || { echo "other HDF5 file: exit $status"; exit 1; }
echo "plot_script: ok"
