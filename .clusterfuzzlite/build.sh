#!/bin/bash -eu
# ClusterFuzzLite calls this with OSS-Fuzz's environment (CXX, CXXFLAGS,
# LIB_FUZZING_ENGINE, OUT); the build is the OSS-Fuzz one.
exec bash "$SRC/sepax/fuzz/oss-fuzz/build.sh"
