#!/usr/bin/env bash
# Prints how many jobs make and ctest may run: the cores this process may use. Not nproc alone: it
# honours OMP_NUM_THREADS, and scripts/test_sanitizers.sh sets that to 1 for its tests (with nproc
# read after it, CI built and tested that step one job at a time and ran past its 90 minutes).
env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc
