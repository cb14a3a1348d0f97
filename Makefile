# SPDX-License-Identifier: BSD-3-Clause
# surfadapt — the one build entry.
#   make            the libraries, the Fortran module and the command-line tool
#   make demo       build and run the demonstration
#   make examples   the example hosts (C, Fortran) and bench/fidelity
#   make test       the fast tier: unit and C tests of the optimized build (80 s once built)
#   make check      build and run every test (C, unit, Fortran, Python, plugin, ABI, install,
#                   command line, sanitizers); what CI runs
#   make check-python  the Python binding's tests alone (Debian's python3-numpy)
#   make bench      benchmarks, one JSON line per case
#   make bench-peers  surfadapt against CGAL's isotropic remeshing, same run, same inputs
#                   (bench/peers; only with Debian's libcgal-dev, never a dependency)
#   make fuzz       FUZZ_SECONDS=60 : each libFuzzer harness for that long (clang)
#   make soak       SOAK_SECONDS=600 SOAK_SEED= : random surfaces through random calls, every
#                   call checked, for that long on one core (tests/soak)
#   make doc        the HTML reference (Doxygen; warnings are errors)
#   make install    PREFIX=/usr/local DESTDIR= : header, libraries, .mod and its .f90, Python
#                   module, tool, pkg-config, CMake
#   make uninstall  PREFIX=/usr/local DESTDIR= : removes exactly what make install put there
# Missing Debian packages are installed when run as root, or named otherwise
# (scripts/ensure-deps.sh).

# The version is written once, in the header: SFA_VERSION_MAJOR, _MINOR and _PATCH give
# VERSION (the shared library's file name, pkg-config and CMake), SFA_ABI_VERSION the
# SONAME's number.
header_number = $(shell awk '$$1 ~ /^.define$$/ && $$2 == "$(1)" { print $$3 }' include/surfadapt.h)
VERSION   := $(call header_number,SFA_VERSION_MAJOR).$(call header_number,SFA_VERSION_MINOR).$(call header_number,SFA_VERSION_PATCH)
SOVERSION := $(call header_number,SFA_ABI_VERSION)
ifneq ($(shell echo '$(VERSION) $(SOVERSION)' | grep -Ex '[0-9]+[.][0-9]+[.][0-9]+ [0-9]+'),$(VERSION) $(SOVERSION))
$(error include/surfadapt.h must define SFA_VERSION_MAJOR, SFA_VERSION_MINOR, SFA_VERSION_PATCH and SFA_ABI_VERSION as whole numbers, one per line; read version "$(VERSION)", ABI "$(SOVERSION)")
endif
PREFIX    ?= /usr/local
DESTDIR   ?=

CC  := gcc
CXX := g++
FC  := gfortran
SAN_CC  := clang
SAN_CXX := clang++

EIGEN_INC := /usr/include/eigen3
WARNINGS  := -Wall -Wextra -Wpedantic -Wshadow
# OpenMP (GCC's libgomp, part of the compiler) for the per-vertex and per-edge loops.
OPENMP    := -fopenmp
# Every product and sum rounded on its own (no fused multiply-add where the target has one,
# which GCC's C++ would otherwise form): the bounds of the geometry's rounding (the exact
# predicates' filters, collision-safe motion's margins) are derived for that, and the
# results are then the same bits on every target.
CXXFLAGS  := -std=c++17 -O2 -g -fPIC -fvisibility=hidden -fvisibility-inlines-hidden -ffp-contract=off $(OPENMP) \
             $(WARNINGS) -Iinclude -Isrc -isystem $(EIGEN_INC)
CFLAGS    := -std=c11 -O2 -g $(WARNINGS) -Iinclude
FFLAGS    := -std=f2008 -O2 -g -Wall -Wextra -fimplicit-none
SAN_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -O1 -g

LIB_NAME  := libsurfadapt.so
LIB_REAL  := lib/$(LIB_NAME).$(VERSION)
LIB_SO    := lib/$(LIB_NAME).$(SOVERSION)
LIB_DEV   := lib/$(LIB_NAME)
LIB_A     := lib/libsurfadapt.a
FLIB_A    := lib/libsurfadapt_fortran.a
FMOD      := lib/fortran/surfadapt.mod
CLI       := bin/surfadapt

LIB_SRCS  := $(sort $(wildcard src/*/*.cpp))
LIB_OBJS  := $(LIB_SRCS:%.cpp=build/%.o)
SAN_OBJS  := $(LIB_SRCS:%.cpp=build/san/%.o)
APP_CXX   := $(sort $(wildcard apps/surfadapt/*.cpp))
APP_C     := $(sort $(wildcard apps/surfadapt/*.c))
APP_OBJS  := $(APP_CXX:%.cpp=build/%.o) $(APP_C:%.c=build/%.o)

# C tests use only the public header and the shared library; unit tests (C++) may use
# internals and link the static library. Both are CMocka programs.
# The tool's mesh readers and writers (mesh_formats.h and one file per format family) are
# shared with the tests, benchmarks and the reader fuzzer.
MESH_IO          := $(addprefix apps/surfadapt/,obj_io.c format_io.c mesh_formats.c stl_io.c ply_io.c medit_io.c \
                      vtk_io.c vtu_io.c)
TEST_SUPPORT     := $(sort $(wildcard tests/c/support/*.c)) $(MESH_IO) apps/surfadapt/icosphere.c \
                    apps/surfadapt/machined_part.c apps/surfadapt/vtu_series.c
TEST_SUPPORT_OBJ := $(TEST_SUPPORT:%.c=build/%.o)
C_TESTS          := $(patsubst tests/c/%.c,build/tests/%,$(sort $(wildcard tests/c/test_*.c)))
UNIT_TESTS       := $(patsubst tests/unit/%.cpp,build/tests/%,$(sort $(wildcard tests/unit/unit_*.cpp)))
SAN_TESTS        := $(patsubst build/tests/%,build/san/tests/%,$(C_TESTS))
# Unit tests of numeric edge cases (cells of non-finite points, fold times at extreme
# scales), also run under the sanitizers: undefined behaviour is what they are about.
SAN_UNIT_TESTS   := build/san/tests/unit_spatial_grid build/san/tests/unit_motion build/san/tests/unit_swept_pairs
ALLOC_HOOK_OBJ   := build/tests/c/alloc_hook/alloc_hook.o
FORTRAN_TEST     := build/tests/test_fortran
FORTRAN_EXAMPLE  := build/examples/vortex_host
C_EXAMPLE        := build/examples/coupler_host
PLUGIN_TEST      := build/tests/test_plugin
# C benchmarks use the public API; C++ ones (bench/*.cpp) time internal steps.
# bench/fidelity is a tool for the flows' checkpoints (bench_flows.sh runs it), not a case.
FIDELITY         := build/bench/fidelity
BENCHES          := $(patsubst bench/%.c,build/bench/%,$(sort $(wildcard bench/*.c))) \
                    $(filter-out $(FIDELITY),$(patsubst bench/%.cpp,build/bench/%,$(sort $(wildcard bench/*.cpp))))

# The fuzz harnesses (see "fuzzing" below); defined here, before `check` names them.
FUZZERS      := $(patsubst tests/fuzz/%.c,%,$(sort $(wildcard tests/fuzz/fuzz_*.c)))
FUZZ_FLAGS   := -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -O1 -g
# The library itself: optimised, and without comparison tracing. Tracing the comparisons
# with constants helps the fuzzer through a reader's keywords, not through geometry, and in
# the library's small fixed-size loops it took over half the time (fuzz_calls ran 2.9 times
# faster without it and at -O2: 16.5 s against 50 s for its corpus).
FUZZ_LIB_FLAGS := $(FUZZ_FLAGS:-O1=-O2) -fno-sanitize-coverage=trace-cmp
FUZZ_OBJS    := $(LIB_SRCS:%.cpp=build/fuzz/%.o)
FUZZ_SECONDS ?= 60
REPLAYS      := $(FUZZERS:%=build/san/tests/replay_%)
# The soak (see "soak" below); `check` runs a short one.
SOAK         := build/soak/soak
SOAK_SECONDS ?= 600
SOAK_SEED    ?= $(shell date +%s)
# 40 surfaces of seed 1: about 15 s, clean today (tests/soak/FINDINGS.md lists the seeds
# that are not, as tests/fuzz/open does for the fuzzers); and the iterations whose findings
# were mended (tests/soak/fixed_seeds, about 10 s).
SOAK_CHECK_SEED       := 1
SOAK_CHECK_ITERATIONS := 40

TEST_RPATH := -Wl,-rpath,'$$ORIGIN/../../lib'

.PHONY: all deps deps-check deps-doc test check check-programs check-python demo examples bench doc install uninstall clean abi-check abi-baseline fuzz \
        soak
.DEFAULT_GOAL := all
# Keep object files of pattern-built programs, so that rebuilds are incremental.
.SECONDARY:

all: deps $(LIB_REAL) $(LIB_SO) $(LIB_DEV) $(LIB_A) $(FLIB_A) $(FMOD) $(CLI)

deps:
	@scripts/ensure-deps.sh build
deps-check:
	@scripts/ensure-deps.sh build check
deps-doc:
	@scripts/ensure-deps.sh build doc

# ------------------------------------------------------------------ library
build/%.o: %.cpp | deps
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -MMD -MP -c $< -o $@

build/%.o: %.c | deps
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -Iapps/surfadapt -MMD -MP -c $< -o $@

# -z nodelete: dlclose() must not unload the library (and OpenMP's runtime with it) while
# OpenMP's idle worker threads still live; a plugin host crashed at exit without it.
$(LIB_REAL): $(LIB_OBJS) src/surfadapt.map
	@mkdir -p $(@D)
	$(CXX) -shared $(OPENMP) -Wl,-soname,$(LIB_NAME).$(SOVERSION) -Wl,--version-script=src/surfadapt.map \
	  -Wl,--no-undefined -Wl,-z,nodelete -o $@ $(LIB_OBJS)

$(LIB_SO): $(LIB_REAL)
	ln -sf $(LIB_NAME).$(VERSION) $@
$(LIB_DEV): $(LIB_SO)
	ln -sf $(LIB_NAME).$(SOVERSION) $@

$(LIB_A): $(LIB_OBJS)
	@mkdir -p $(@D)
	rm -f $@ && ar rcs $@ $^

# ------------------------------------------------------------------ Fortran
build/fortran/surfadapt.o: bindings/fortran/surfadapt.f90 | deps
	@mkdir -p $(@D) lib/fortran
	$(FC) $(FFLAGS) -fPIC -J lib/fortran -c $< -o $@
$(FMOD): build/fortran/surfadapt.o
$(FLIB_A): build/fortran/surfadapt.o
	rm -f $@ && ar rcs $@ $^

# ------------------------------------------------------------------ command-line tool
$(CLI): $(APP_OBJS) $(LIB_SO) $(LIB_DEV)
	@mkdir -p $(@D)
	$(CXX) $(OPENMP) -o $@ $(APP_OBJS) -Llib -lsurfadapt -Wl,-rpath,'$$ORIGIN/../lib'

# `make demo`, `make test` and `make check` build what they need in a make of their own,
# with one job per core (JOBS=N to change), unless the caller gave -j, whose jobs they
# then share. Run them alone, not beside `all` under -j: the two makes would build the
# same files at once.
JOBS ?= $(shell nproc 2>/dev/null || echo 1)
PARALLEL = $(if $(filter -j%,$(MAKEFLAGS)),,-j$(or $(JOBS),1))

demo: deps
	@$(MAKE) --no-print-directory $(PARALLEL) all
	@mkdir -p build/demo
	$(CLI) demo --out build/demo

# The example hosts (bindings/fortran/examples, examples/) and bench/fidelity, the shape
# error by backtracing; `make check` builds and runs them too.
examples: all $(C_EXAMPLE) $(FORTRAN_EXAMPLE) $(FIDELITY)

# ------------------------------------------------------------------ tests
build/tests/test_%: build/tests/c/test_%.o $(TEST_SUPPORT_OBJ) $(ALLOC_HOOK_OBJ) $(LIB_SO) $(LIB_DEV)
	@mkdir -p $(@D)
	$(CXX) -o $@ $(filter %.o,$^) -Llib -lsurfadapt -lcmocka -lm $(TEST_RPATH)

build/tests/c/%.o: tests/c/%.c | deps
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -Itests/c -Iapps/surfadapt -MMD -MP -c $< -o $@

$(ALLOC_HOOK_OBJ): tests/c/alloc_hook/alloc_hook.cpp | deps
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -Itests/c -c $< -o $@

# The predicates' test checks them against exact rational arithmetic (GMP, test-only).
build/tests/unit_predicates: UNIT_LIBS := -lgmpxx -lgmp
# The repair of the command-line tool, tested with the library that judges its result.
build/tests/unit_repair: build/apps/surfadapt/repair.o
build/tests/unit_repair: UNIT_LIBS := build/apps/surfadapt/repair.o
$(UNIT_TESTS): build/tests/%: tests/unit/%.cpp $(LIB_A) $(TEST_SUPPORT_OBJ)
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -Itests/c -Iapps/surfadapt -MMD -MP -o $@ $< $(TEST_SUPPORT_OBJ) $(LIB_A) -lcmocka $(UNIT_LIBS) -lm

# The same C tests against the library's objects built with ASan + UBSan (static link),
# without OpenMP (clang's runtime is another package; the loops then run serially).
build/san/%.o: %.cpp | deps
	@mkdir -p $(@D)
	$(SAN_CXX) $(filter-out -O2 $(OPENMP),$(CXXFLAGS)) -Wno-unknown-pragmas -Wno-unused-command-line-argument $(SAN_FLAGS) -MMD -MP -c $< -o $@
build/san/%.o: %.c | deps
	@mkdir -p $(@D)
	$(SAN_CC) $(filter-out -O2,$(CFLAGS)) $(SAN_FLAGS) -DSFA_NO_ALLOC_HOOK -Itests/c -Iapps/surfadapt \
	  -MMD -MP -c $< -o $@
build/san/tests/test_%: build/san/tests/c/test_%.o $(TEST_SUPPORT:%.c=build/san/%.o) $(SAN_OBJS)
	@mkdir -p $(@D)
	$(SAN_CXX) $(SAN_FLAGS) -o $@ $^ -lcmocka -lm
build/san/tests/unit_%: tests/unit/unit_%.cpp $(TEST_SUPPORT:%.c=build/san/%.o) $(SAN_OBJS)
	@mkdir -p $(@D)
	$(SAN_CXX) $(filter-out -O2 $(OPENMP),$(CXXFLAGS)) -Wno-unknown-pragmas -Itests/c -Iapps/surfadapt $(SAN_FLAGS) \
	  -o $@ $^ -lcmocka -lm

$(FORTRAN_TEST): tests/fortran/test_surfadapt.f90 $(FLIB_A) $(FMOD) $(LIB_SO) $(LIB_DEV)
	@mkdir -p $(@D)/fortran
	$(FC) $(FFLAGS) -Ilib/fortran -J $(@D)/fortran -o $@ $< $(FLIB_A) -Llib -lsurfadapt $(TEST_RPATH)

# The example host, built the way a Fortran host builds against the library.
$(FORTRAN_EXAMPLE): bindings/fortran/examples/vortex_host.f90 $(FLIB_A) $(FMOD) $(LIB_SO) $(LIB_DEV)
	@mkdir -p $(@D)
	$(FC) $(FFLAGS) -Ilib/fortran -J $(@D) -o $@ $< $(FLIB_A) -Llib -lsurfadapt -Wl,-rpath,'$$ORIGIN/../../lib'

# The C example host (a coupler carrying its data through sfa_adapt), built the same way.
$(C_EXAMPLE): examples/coupler_host.c $(LIB_SO) $(LIB_DEV)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -o $@ $< -Llib -lsurfadapt -lm -Wl,-rpath,'$$ORIGIN/../../lib'

$(PLUGIN_TEST): tests/plugin/test_dlopen.c | deps
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -o $@ $< -ldl

# The fast tier, for the edit-build-test loop: every unit and C test program, in the
# optimized build; no Fortran, plugin, ABI, install, command-line or sanitizer run.
# OpenMP threads that wait at a barrier sleep instead of spinning (unless the caller chose
# otherwise): on cores shared with other work, spinning made unit_crossing_guard and
# test_adapt ten to twenty times slower (130 s instead of 7 s). Results do not depend on it.
test: deps-check
	@$(MAKE) --no-print-directory $(PARALLEL) $(UNIT_TESTS) $(C_TESTS)
	@OMP_WAIT_POLICY=$${OMP_WAIT_POLICY:-passive} scripts/run-tests.sh $(UNIT_TESTS) $(C_TESTS)

# What `make check` runs, built in parallel (one job per core, JOBS=N to change) once
# every package is there, so that no compiler waits for apt-get; the tests then run one
# after another.
CHECK_PROGRAMS := all $(C_TESTS) $(UNIT_TESTS) $(FORTRAN_TEST) $(FORTRAN_EXAMPLE) $(C_EXAMPLE) $(PLUGIN_TEST) $(FIDELITY) \
                  $(SAN_TESTS) $(SAN_UNIT_TESTS) $(REPLAYS) $(SOAK)
check-programs: $(CHECK_PROGRAMS)
check: deps-check
	@$(MAKE) --no-print-directory $(PARALLEL) check-programs
	@scripts/run-tests.sh $(C_TESTS) $(UNIT_TESTS) $(FORTRAN_TEST) "$(FORTRAN_EXAMPLE) 60" $(C_EXAMPLE) \
	  "OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive $(SOAK) --iterations $(SOAK_CHECK_ITERATIONS) --seed $(SOAK_CHECK_SEED)" \
	  "OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive $(SOAK) --seeds tests/soak/fixed_seeds" \
	  tests/python/run.sh "$(PLUGIN_TEST) $(abspath $(LIB_SO))" "$(MAKE) --no-print-directory abi-check" \
	  tests/install/test_install.sh tests/cli/test_features_cli.sh tests/cli/test_remesh_cli.sh tests/cli/test_flows_cli.sh \
	  tests/cli/test_formats_cli.sh tests/cli/test_repair_cli.sh \
	  tests/cli/test_fidelity.sh tests/readme/test_readme_programs.sh $(SAN_TESTS) $(SAN_UNIT_TESTS) \
	  $(foreach f,$(FUZZERS),"build/san/tests/replay_$(f) tests/fuzz/corpus/$(f) tests/fuzz/crashes/$(f)")

# The Python binding (bindings/python) needs nothing built but the shared library: the
# script runs Debian's /usr/bin/python3, which python3-numpy serves (see the script).
check-python: deps-check $(LIB_SO) $(LIB_DEV)
	@scripts/run-tests.sh tests/python/run.sh

# ------------------------------------------------------------------ fuzzing
# libFuzzer harnesses, tests/fuzz/fuzz_*.c: each checks the library's contract after every
# call (tests/fuzz/contract.h). `make fuzz` builds them against the library instrumented
# for coverage, with ASan + UBSan, and runs each for FUZZ_SECONDS (default 60) from its
# committed corpus (tests/fuzz/corpus/NAME), keeping what it finds in build/fuzz/corpus
# and any crash in build/fuzz/crashes (scripts/fuzz.sh). A crash, once fixed, goes to
# tests/fuzz/crashes/NAME. `make check` replays both directories in the sanitizer build.

build/fuzz/%.o: %.cpp | deps
	@mkdir -p $(@D)
	$(SAN_CXX) $(filter-out -O2 $(OPENMP),$(CXXFLAGS)) -Wno-unknown-pragmas -Wno-unused-command-line-argument \
	  $(FUZZ_LIB_FLAGS) -MMD -MP -c $< -o $@
build/fuzz/%.o: %.c | deps
	@mkdir -p $(@D)
	$(SAN_CC) $(filter-out -O2,$(CFLAGS)) $(FUZZ_FLAGS) -DSFA_NO_ALLOC_HOOK -Itests/c -Iapps/surfadapt \
	  -MMD -MP -c $< -o $@
build/fuzz/bin/%: build/fuzz/tests/fuzz/%.o $(TEST_SUPPORT:%.c=build/fuzz/%.o) $(FUZZ_OBJS)
	@mkdir -p $(@D)
	$(SAN_CXX) -fsanitize=fuzzer,address,undefined -o $@ $^ -lm
build/san/tests/replay_%: build/san/tests/fuzz/%.o build/san/tests/fuzz/replay.o $(TEST_SUPPORT:%.c=build/san/%.o) \
                          $(SAN_OBJS)
	@mkdir -p $(@D)
	$(SAN_CXX) $(SAN_FLAGS) -o $@ $^ -lm
fuzz: deps-check $(FUZZERS:%=build/fuzz/bin/%)
	@scripts/fuzz.sh $(FUZZ_SECONDS) $(FUZZERS)

# ------------------------------------------------------------------ soak
# tests/soak: random valid surfaces through random motion, smoothing and adaptation, every
# call checked (README, "Reliability"). `make soak SOAK_SECONDS=600` runs it that long on one
# thread, niced, from SOAK_SEED (default: the time) and prints one JSON line; each finding
# is printed with the seed that replays it (build/soak/soak --seed S --replay). `make check`
# runs a fixed seed for a few seconds, so that the harness cannot rot.
$(SOAK): tests/soak/soak.c tests/soak/surfaces.c tests/soak/surfaces.h tests/fuzz/contract.h $(TEST_SUPPORT_OBJ) \
         $(LIB_SO) $(LIB_DEV)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -Itests/c -Itests/fuzz -Iapps/surfadapt -o $@ $(filter %.c,$^) $(TEST_SUPPORT_OBJ) -Llib -lsurfadapt \
	  -lm $(TEST_RPATH)
soak: deps $(SOAK)
	@OMP_NUM_THREADS=$${OMP_NUM_THREADS:-1} OMP_WAIT_POLICY=$${OMP_WAIT_POLICY:-passive} \
	  nice -n 10 $(SOAK) --seconds $(SOAK_SECONDS) --seed $(SOAK_SEED)

# ------------------------------------------------------------------ ABI
# abidiff exit status is a bit set: 4 = the ABI changed (additions), 8 = an incompatible
# change. Additions pass; anything incompatible fails. To accept a change on purpose
# (new symbols), run `make abi-baseline` and commit tests/abi/libsurfadapt.abi.
ABI_BASELINE := tests/abi/libsurfadapt.abi
abi-check: $(LIB_REAL)
	@scripts/abi-check.sh $(LIB_REAL) $(ABI_BASELINE)
# The script writes the baseline with the same abidw options it checks with.
abi-baseline: $(LIB_REAL)
	@scripts/abi-check.sh --update $(LIB_REAL) $(ABI_BASELINE)

# ------------------------------------------------------------------ benchmarks
build/bench/%: bench/%.c $(TEST_SUPPORT_OBJ) $(LIB_SO) $(LIB_DEV)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -Itests/c -Iapps/surfadapt -o $@ $< $(TEST_SUPPORT_OBJ) -Llib -lsurfadapt -lm \
	  $(TEST_RPATH)
build/bench/%: bench/%.cpp $(TEST_SUPPORT_OBJ) $(LIB_A)
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -Ibench -Iapps/surfadapt -o $@ $< $(TEST_SUPPORT_OBJ) $(LIB_A) -lm
# bench_collision moves its surface by the tool's Enright field; it and bench_topology also
# time their searches on the flows' checkpoints (bench/checkpoint_mesh.hpp; the mesh
# readers are in TEST_SUPPORT).
BENCH_CHECKPOINT_OBJS := $(addprefix build/apps/surfadapt/,flows.o checkpoint.o)
build/bench/bench_collision build/bench/bench_topology: build/bench/%: bench/%.cpp bench/checkpoint_mesh.hpp \
                                                        $(BENCH_CHECKPOINT_OBJS) $(TEST_SUPPORT_OBJ) $(LIB_A)
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -Ibench -Iapps/surfadapt -o $@ $< $(BENCH_CHECKPOINT_OBJS) $(TEST_SUPPORT_OBJ) $(LIB_A) -lm
# The backtrace needs the flows' velocity fields and the checkpoint header of the tool.
$(FIDELITY): bench/fidelity.cpp bench/surface_resolution.hpp build/apps/surfadapt/flows.o \
             build/apps/surfadapt/checkpoint.o build/apps/surfadapt/obj_io.o build/apps/surfadapt/format_io.o $(LIB_A)
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -Iapps/surfadapt -o $@ $(filter-out %.hpp,$^) -lm
bench: all $(BENCHES) $(FIDELITY)
	@for b in $(BENCHES); do $$b || exit 1; done
	@bench/bench_flows.sh

# `make bench-peers`: surfadapt against CGAL's isotropic remeshing in the same run
# (bench/peers/run.sh): the Enright test tracked by both, the shape error of both by
# backtracing, and static remeshing of the demo's part and of jittered spheres. Only these
# two programs include CGAL (header-only; Debian's libcgal-dev, which brings GMP and MPFR):
# never the library, the tool, `make all` or `make check`. Without CGAL the target says
# which package to install and fails, before building anything.
PEER_ENRIGHT      := build/bench/peers/cgal_enright
PEER_STATIC       := build/bench/peers/cgal_static
PEER_ENRIGHT_OBJS := $(addprefix build/apps/surfadapt/,flows.o icosphere.o checkpoint.o obj_io.o format_io.o)
PEER_STATIC_OBJS  := $(addprefix build/apps/surfadapt/,machined_part.o icosphere.o)
# Optimised as CGAL's own builds are (-DNDEBUG: its checks are not part of what is timed).
PEER_FLAGS := -std=c++17 -O2 -DNDEBUG $(OPENMP) $(WARNINGS) -Iinclude -Iapps/surfadapt -Ibench -Ibench/peers
PEER_LIBS  := -Llib -lsurfadapt -lgmp -lmpfr -lm -Wl,-rpath,'$$ORIGIN/../../../lib'
$(PEER_ENRIGHT): bench/peers/cgal_enright.cpp $(PEER_ENRIGHT_OBJS) $(LIB_SO) $(LIB_DEV)
	@mkdir -p $(@D)
	$(CXX) $(PEER_FLAGS) -MMD -MP -o $@ $< $(PEER_ENRIGHT_OBJS) $(PEER_LIBS)
$(PEER_STATIC): bench/peers/cgal_static.cpp $(PEER_STATIC_OBJS) $(LIB_SO) $(LIB_DEV)
	@mkdir -p $(@D)
	$(CXX) $(PEER_FLAGS) -MMD -MP -o $@ $< $(PEER_STATIC_OBJS) $(PEER_LIBS)
.PHONY: bench-peers
bench-peers:
	@echo '#include <CGAL/version.h>' | $(CXX) -x c++ -E - >/dev/null 2>&1 || \
	  { echo "surfadapt: make bench-peers needs CGAL, Debian's libcgal-dev (apt-get install libcgal-dev); nothing else does" >&2; \
	    exit 1; }
	@$(MAKE) --no-print-directory all $(FIDELITY) $(PEER_ENRIGHT) $(PEER_STATIC)
	@bench/peers/run.sh

# ------------------------------------------------------------------ documentation
doc: deps-doc
	@mkdir -p build/doc
	doxygen doc/Doxyfile

# ------------------------------------------------------------------ install
# Both scripts take the list of what is installed from scripts/install-manifest.sh.
install: all
	@scripts/install.sh "$(DESTDIR)" "$(PREFIX)" "$(VERSION)" "$(SOVERSION)"
uninstall:
	@scripts/uninstall.sh "$(DESTDIR)" "$(PREFIX)" "$(VERSION)" "$(SOVERSION)"

clean:
	rm -rf build lib bin

-include $(shell find build -name '*.d' 2>/dev/null)
