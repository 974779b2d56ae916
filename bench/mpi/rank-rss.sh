#!/bin/sh
# Runs a command under /usr/bin/time -v, writing PREFIX.<rank> (the MPI rank
# from OpenMPI's environment, 0 without mpirun): one peak RSS per rank.
#   mpirun -np 2 bench/mpi/rank-rss.sh PREFIX command...
prefix=$1
shift
exec /usr/bin/time -v -o "$prefix.${OMPI_COMM_WORLD_RANK:-0}" "$@"
