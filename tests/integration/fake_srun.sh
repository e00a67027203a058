#!/bin/sh
# Stands in for Slurm's srun in tests (Slurm is not installed here): records its arguments,
# one a line, in $FAKE_SRUN_DIR/$COSIM_PARTICIPANT.args, then runs the command that follows
# its options, once, on this host.
printf '%s\n' "$@" > "$FAKE_SRUN_DIR/$COSIM_PARTICIPANT.args"
while [ $# -gt 0 ]; do
  case "$1" in
    --*) shift ;;
    *) break ;;
  esac
done
exec "$@"
