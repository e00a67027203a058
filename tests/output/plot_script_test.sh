#!/usr/bin/env bash
# plot_script_test.sh MAKE_SAMPLE_RUN PLOT WORKDIR: scripts/plot on a full run, a run
# without bodies, one body and a slice of the velocity, and bad input.
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

"$plot" "$work/run.h5" --out "$work/one" --bodies ball --slice z=0.05 --at 1.0
test -s "$work/one/run-slice.png" && test -s "$work/one/run-trajectories.png"
"$plot" "$work/empty.h5" --slice x=0 2>"$work/err" && { echo "a slice without fields"; exit 1; }
for bad in "--slice q=1" "--slice z=3" "--bodies nobody"; do
  status=0
  "$plot" "$work/run.h5" --out "$work/bad" $bad 2>"$work/err" || status=$?
  [ "$status" = 2 ] && [ "$(wc -l <"$work/err")" = 1 ] || { echo "$bad: exit $status"; exit 1; }
done
test ! -e "$work/bad"

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
