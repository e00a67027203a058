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
# The plane's velocity against the sample's u = (-y, x, 0), and the ball's surface points
# (radius 0.1 at height 0.1 cos(2 pi t)) picked within half a cell of the plane.
/usr/bin/python3 - "$plot" "$work/run.h5" <<'PY'
import importlib.machinery, importlib.util, sys
import numpy as np
loader = importlib.machinery.SourceFileLoader("plot", sys.argv[1])
plot = importlib.util.module_from_spec(importlib.util.spec_from_loader("plot", loader))
loader.exec_module(plot)
time, nodes, u, points = plot.plane_of_run(sys.argv[2], (2, 0.05), 1.0)  # z = 0.05 cuts the layer -0.1 .. 0.1
assert time == 1.0, time
x, y = (0.5 * (n[1:] + n[:-1]) for n in nodes[:2])
assert u.shape == (4, 6, 3), u.shape
assert np.allclose(u[..., 0], -y[:, None]) and np.allclose(u[..., 1], x[None, :]) and np.allclose(u[..., 2], 0)
assert len(points) == 8 and np.allclose(points[:, 2], 0.1), points  # the ball at z = 0.1, inside the layer
time, nodes, u, points = plot.plane_of_run(sys.argv[2], (0, 0.1), 1.0)  # x = 0.1 cuts the cells 0 .. 1/3
assert u.shape == (5, 4, 3) and np.allclose(u[..., 1], 1 / 6), u[..., 1]
assert len(points) == 5 and np.all(points[:, 0] >= 0.1 - 1 / 6), points  # x within 1/6 of the plane
time, _, _, points = plot.plane_of_run(sys.argv[2], (2, 0.05), 0.6)  # the write at 0.5: the ball at -0.1
assert time == 0.5 and len(points) == 0, (time, points)
PY
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
