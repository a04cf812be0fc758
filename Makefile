# shitsukan — the build rules (GNU make). Targets: README.md ("The two commands"); how the
# build works: docs/DESIGN.md ("How it is built"). Long checks are scripts beside what they
# check; packages come through tools/ensure_packages.sh. Sources are discovered (lib/, tests/,
# paper_figures/, examples/, cli/). Each step prints "[n/N] file"; V=1 prints the commands.

CXX      ?= g++
AR       ?= ar
PREFIX   ?= /usr/local
BUILD    := build
JOBS     ?= $(shell nproc 2>/dev/null || echo 2)
FIGURES_ARGS ?=
BENCH_ARGS ?=

# docs/DESIGN.md: same inputs, same bits -> no FMA contraction, no fast-math.
WARN     := -Wall -Wextra -Wpedantic
ifdef CI
WARN     += -Werror
endif
override CXXFLAGS := -std=c++17 -O2 $(WARN) -ffp-contract=off $(CXXFLAGS)
override CPPFLAGS := -Ilib -Ipaper_figures $(CPPFLAGS)
# LeakSanitizer needs ptrace-free processes; override with ASAN_OPTIONS=detect_leaks=0 where
# a container forbids it.
ASAN_OPTIONS ?= detect_leaks=1
SAN_FLAGS := -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all
SMALL_FLAGS := -fno-exceptions -fno-rtti -DSHITSUKAN_SMALL_DEVICE -Wdouble-promotion -fstack-usage

LIB_SRCS     := $(shell find lib -name '*.cpp' 2>/dev/null | LC_ALL=C sort)
FIG_SRCS     := $(shell find paper_figures -name '*.cpp' -not -path 'paper_figures/out/*' 2>/dev/null | LC_ALL=C sort)
TEST_SRCS    := $(sort $(wildcard tests/*.cpp))
BENCH_SRCS   := $(sort $(wildcard tests/bench/*.cpp))
EXAMPLE_SRCS := $(sort $(wildcard examples/*.cpp))
CLI_SRCS     := $(sort $(wildcard cli/*.cpp))
# The small-device core (files tagged "// small-device: yes"), listed once in
# lib/shitsukan/small_device_sources.txt by tools/small_sources.sh; CMake and mcu.mk read it too.
SMALL_SRCS   := $(shell grep -v '^\#' lib/shitsukan/small_device_sources.txt 2>/dev/null)

# Objects depend on a stamp named after the flags, so `CI=1 make test` after a plain build
# really recompiles with -Werror instead of reusing objects built without it.
FLAGS_HASH  := $(shell printf '%s' '$(CXX) $(CPPFLAGS) $(CXXFLAGS)' | cksum | cut -d' ' -f1)
FLAGS_STAMP := $(BUILD)/.flags-$(FLAGS_HASH)

LIB_OBJS   := $(LIB_SRCS:%.cpp=$(BUILD)/obj/%.o)
FIG_OBJS   := $(FIG_SRCS:%.cpp=$(BUILD)/obj/%.o)
TEST_OBJS  := $(TEST_SRCS:%.cpp=$(BUILD)/obj/%.o)
BENCH_OBJS := $(BENCH_SRCS:%.cpp=$(BUILD)/obj/%.o)
CLI_OBJS   := $(CLI_SRCS:%.cpp=$(BUILD)/obj/%.o)
CLI        := $(BUILD)/shitsukan
SAN_OBJS   := $(LIB_SRCS:%.cpp=$(BUILD)/san/%.o) $(TEST_SRCS:%.cpp=$(BUILD)/san/%.o)
SMALL_CPPS := $(filter %.cpp,$(SMALL_SRCS))
SMALL_HPPS := $(filter %.hpp,$(SMALL_SRCS))
SMALL_OBJS := $(SMALL_CPPS:%.cpp=$(BUILD)/small/%.o)
EXAMPLES   := $(EXAMPLE_SRCS:examples/%.cpp=$(BUILD)/examples/%)
LIBRARY    := $(BUILD)/libshitsukan.a

.PHONY: all test test-sanitize figures examples bench check-small check-api test-consumers \
        check-references install deps bench-deps consumer-deps mcu-deps clean fuzz fuzz-deps \
        figures-determinism cli test-cli test-mcu bench-mcu footprint-mcu check-manuals \
        check-lengths measurements

# The top-level targets run one at a time (each builds in parallel inside its own sub-make), so
# `make -j test figures` cannot build the library twice at once. tools/make_steps.sh counts the
# sub-make's steps first, so that each prints "[n/N] file" (`$(call step,file)` below).
SUBMAKE := bash tools/make_steps.sh $(MAKE) --no-print-directory SHITSUKAN_SUBMAKE=1 -j$(JOBS)
ifndef SHITSUKAN_SUBMAKE
.NOTPARALLEL:
endif
# $(call step,what): makes the target's directory and prints "[n/N] what" (V=1: nothing).
ifeq ($(V),1)
Q :=
step = @mkdir -p $(@D)
else
Q := @
step = @mkdir -p $(@D) && sh tools/progress.sh '$(SHITSUKAN_STEPS_FILE)' '$(SHITSUKAN_STEPS)' '$(1)'
endif

# ---- packages: installed when missing (apt-get as root, waiting for the apt lock), otherwise
# named; "path:package" pairs (tools/ensure_packages.sh) ----
REQUIRED := /usr/include/doctest/doctest.h:doctest-dev /usr/include/stb/stb_image_write.h:libstb-dev
BENCH_REQUIRED := /usr/include/libnoise/noise.h:libnoise-dev /usr/include/boost/polygon/voronoi.hpp:libboost-dev \
                  /usr/include/CGAL/Surface_mesh.h:libcgal-dev /usr/include/CGAL/Delaunay_triangulation_2.h:libcgal-dev
# The checks written in Python (tools/*.py: module map, manual snippets, function lengths).
PY_REQUIRED := /usr/bin/python3:python3
# test-cli reads the tool's EXR maps back through an independent reader (tests/cli/exr_readback.py).
CLI_REQUIRED := /usr/share/doc/python3-openimageio/copyright:python3-openimageio /usr/share/doc/python3-numpy/copyright:python3-numpy
CONSUMER_REQUIRED := /usr/bin/cmake:cmake /usr/bin/pkg-config:pkg-config /usr/bin/git:git
FUZZ_REQUIRED := /usr/bin/clang++:clang
ensure_packages = @bash tools/ensure_packages.sh $(1)

deps:
	$(call ensure_packages,$(REQUIRED))
bench-deps: deps
	$(call ensure_packages,$(BENCH_REQUIRED))
consumer-deps: deps
	$(call ensure_packages,$(CONSUMER_REQUIRED))
fuzz-deps:
	$(call ensure_packages,$(FUZZ_REQUIRED))

# ---- the two set-up commands, and the other programs ----
test: deps
	@$(SUBMAKE) $(BUILD)/tests
	$(BUILD)/tests

figures: deps
	@$(SUBMAKE) $(BUILD)/paper_figures
	$(BUILD)/paper_figures $(FIGURES_ARGS)

all: deps
	@$(SUBMAKE) $(LIBRARY) $(EXAMPLES) $(BUILD)/paper_figures $(CLI)

cli:
	@$(SUBMAKE) $(CLI)

# The tool's good runs make their files, each bad flag exits 2 naming it (tests/cli/run.sh);
# failed writes leave nothing behind and name the reason (tests/cli/faults.sh).
test-cli: deps
	$(call ensure_packages,$(CLI_REQUIRED))
	@$(SUBMAKE) $(CLI)
	bash tests/cli/run.sh $(CLI)
	bash tests/cli/faults.sh $(CLI)

test-sanitize: deps
	@$(SUBMAKE) $(BUILD)/tests-sanitize
	ASAN_OPTIONS=$(ASAN_OPTIONS) UBSAN_OPTIONS=print_stacktrace=1 $(BUILD)/tests-sanitize

examples: deps
	@$(SUBMAKE) $(EXAMPLES)
	@mkdir -p $(BUILD)/examples/out
	@for e in $(EXAMPLES); do echo "== $$e"; (cd $(BUILD)/examples/out && ../$$(basename $$e)) || exit 1; done

bench: bench-deps
	@$(SUBMAKE) $(BUILD)/bench
	$(BUILD)/bench $(BENCH_ARGS)

# docs/MEASUREMENTS.md generated from the bench's output (kept as docs/bench_output.txt) by
# tools/bench_measurements.py, with the CPU time of all figures (paper_figures' `bench:` line);
# MEASUREMENTS_FROM=<saved output> skips running the bench.
MEASUREMENTS_FROM ?=
measurements: bench-deps
	$(call ensure_packages,$(PY_REQUIRED))
ifeq ($(MEASUREMENTS_FROM),)
	@$(SUBMAKE) $(BUILD)/bench
	$(BUILD)/bench $(BENCH_ARGS) > $(BUILD)/bench_output.txt
	@$(SUBMAKE) $(BUILD)/paper_figures
	$(BUILD)/paper_figures --jobs $(JOBS) | grep '^bench:' >> $(BUILD)/bench_output.txt
	cp $(BUILD)/bench_output.txt docs/bench_output.txt
	python3 tools/bench_measurements.py docs/bench_output.txt docs/MEASUREMENTS.md
else
	python3 tools/bench_measurements.py $(MEASUREMENTS_FROM) docs/MEASUREMENTS.md
endif

# ---- checks (each a script or a tool beside what it checks) ----
# The small-device core allocates nothing, throws nothing, calls no stdio, keeps each function's
# stack within budget and includes no std container (tools/check_small.sh).
check-small:
	@$(SUBMAKE) $(SMALL_OBJS)
	@CXX='$(CXX)' CPPFLAGS='$(CPPFLAGS)' CXXFLAGS='$(CXXFLAGS)' SMALL_FLAGS='$(SMALL_FLAGS)' \
	  bash tools/check_small.sh $(BUILD)/small

# Headers compile alone, the umbrella header is complete, only shitsukan symbols are exported,
# a program with its own stb links, PNGs without the stb header, a dropped Status is a compile
# error, README's module map matches the tree, required outputs are references, modules include
# what docs/DESIGN.md's graph allows.
check-api: deps
	$(call ensure_packages,$(PY_REQUIRED))
	@$(SUBMAKE) $(LIBRARY)
	@CXX='$(CXX)' CPPFLAGS='$(CPPFLAGS)' CXXFLAGS='$(CXXFLAGS)' JOBS=$(JOBS) \
	  bash tools/check_api.sh $(LIBRARY) $(BUILD)/api

# Every header's manual example ("// Manual") compiled against the library and, unless tagged
# "// Manual (compile-only)", run (tools/extract_manuals.py; programs in build/manuals/).
check-manuals: deps
	$(call ensure_packages,$(PY_REQUIRED))
	@$(SUBMAKE) $(LIBRARY)
	@python3 tools/extract_manuals.py --build --out $(BUILD)/manuals --cxx '$(CXX)' \
	  --flags '$(CPPFLAGS) $(CXXFLAGS) -O0 -Wno-unused-variable -Wno-unused-but-set-variable' \
	  --lib $(LIBRARY) -j $(JOBS)

# No function over 100 lines in lib/, cli/, paper_figures/, examples/, ports/
# (tools/function_lengths.py lists the ones over); this
# Makefile within 300 lines and README.md within 20 KB (tools/check_sizes.sh).
check-lengths:
	$(call ensure_packages,$(PY_REQUIRED))
	@python3 tools/function_lengths.py lib cli paper_figures examples ports
	@bash tools/check_sizes.sh

# Nothing cites an issue or a file outside the repository (tools/check_references.py).
check-references:
	$(call ensure_packages,$(PY_REQUIRED))
	@python3 tools/check_references.py

# tests/consumer built four ways (add_subdirectory, FetchContent, find_package, pkg-config).
test-consumers: consumer-deps
	JOBS=$(JOBS) CXX=$(CXX) bash tests/consumer/run.sh

# The quick figures from g++ (on 2 threads and on 1) and clang++ must be the same files.
figures-determinism: deps fuzz-deps
	@$(SUBMAKE) $(BUILD)/paper_figures
	@$(SUBMAKE) BUILD=$(BUILD)/clang CXX=clang++ CI= $(BUILD)/clang/paper_figures
	@bash tools/figures_determinism.sh $(BUILD) $(BUILD)/paper_figures $(BUILD)/clang/paper_figures

# ---- fuzzing: libFuzzer harnesses (clang, ASan + UBSan) over the public entry points ----
# fuzz/run.sh replays each committed corpus, then explores for FUZZ_SECONDS; fuzz/README.md
# says what FUZZ_SEED, FUZZ_STRICT and FUZZ_TIMEOUT (per input, wall clock, chosen there) do.
FUZZ_CXX     ?= clang++
FUZZ_SECONDS ?= 20
FUZZ_SEED    ?= 1
FUZZ_STRICT  ?= 1
FUZZ_TIMEOUT ?= 120
FUZZ_FLAGS   := -std=c++17 -O1 -g -fno-omit-frame-pointer -ffp-contract=off \
                -fsanitize=address,undefined -fno-sanitize-recover=all
FUZZERS      := $(patsubst fuzz/%.cpp,$(BUILD)/fuzz/%,$(sort $(wildcard fuzz/fuzz_*.cpp)))
FUZZ_OBJS    := $(LIB_SRCS:%.cpp=$(BUILD)/fuzzobj/%.o)
# kept between runs (only prerequisites of the pattern rule below, make would delete them);
# compiled with libFuzzer's coverage (fuzzer-no-link) so that it guides into the library
.SECONDARY: $(FUZZ_OBJS)

fuzz: fuzz-deps
	@$(SUBMAKE) $(FUZZERS)
	@FUZZ_SECONDS=$(FUZZ_SECONDS) FUZZ_SEED=$(FUZZ_SEED) FUZZ_STRICT=$(FUZZ_STRICT) \
	  FUZZ_TIMEOUT=$(FUZZ_TIMEOUT) bash fuzz/run.sh $(BUILD)/fuzz

$(BUILD)/fuzz/%: fuzz/%.cpp fuzz/fuzz_input.hpp $(FUZZ_OBJS)
	$(call step,link $@)
	$(Q)$(FUZZ_CXX) $(CPPFLAGS) $(FUZZ_FLAGS) -fsanitize=fuzzer -o $@ $< $(FUZZ_OBJS)

# stb_image (inside image_read.cpp) hands memcpy a null pointer for 0 bytes of an empty IDAT
# chunk (harmless; found by fuzz_readers): UBSan's nonnull-attribute check is off for that file.
$(BUILD)/fuzzobj/lib/shitsukan/image/image_read.o: FUZZ_FLAGS += -fno-sanitize=nonnull-attribute

# ---- linking ----
$(LIBRARY): $(LIB_OBJS)
	$(call step,ar $@)
	@rm -f $@
	$(Q)$(AR) rcs $@ $^

$(BUILD)/tests: $(TEST_OBJS) $(LIBRARY)
	$(call step,link $@)
	$(Q)$(CXX) $(CXXFLAGS) -o $@ $(TEST_OBJS) $(LIBRARY)

$(BUILD)/tests-sanitize: $(SAN_OBJS)
	$(call step,link $@)
	$(Q)$(CXX) $(CXXFLAGS) $(SAN_FLAGS) -o $@ $(SAN_OBJS)

# Figure objects are linked directly (not through an archive): they register themselves.
# -pthread: the driver renders figures on threads (--jobs).
$(BUILD)/paper_figures: $(FIG_OBJS) $(LIBRARY)
	$(call step,link $@)
	$(Q)$(CXX) $(CXXFLAGS) -pthread -o $@ $(FIG_OBJS) $(LIBRARY)

$(BUILD)/bench: $(BENCH_OBJS) $(LIBRARY)
	$(call step,link $@)
	$(Q)$(CXX) $(CXXFLAGS) -o $@ $(BENCH_OBJS) $(LIBRARY) -lnoise -lmpfr -lgmp

$(CLI): $(CLI_OBJS) $(LIBRARY)
	$(call step,link $@)
	$(Q)$(CXX) $(CXXFLAGS) -o $@ $(CLI_OBJS) $(LIBRARY)

$(BUILD)/examples/%: $(BUILD)/obj/examples/%.o $(LIBRARY)
	$(call step,link $@)
	$(Q)$(CXX) $(CXXFLAGS) -o $@ $< $(LIBRARY)

# ---- compiling ----
$(FLAGS_STAMP):
	@mkdir -p $(@D)
	@rm -f $(BUILD)/.flags-*
	@touch $@

$(BUILD)/obj/%.o: %.cpp $(FLAGS_STAMP)
	$(call step,$<)
	$(Q)$(CXX) $(CPPFLAGS) $(CXXFLAGS) -MMD -MP -c $< -o $@

$(BUILD)/san/%.o: %.cpp $(FLAGS_STAMP)
	$(call step,$< (sanitizers))
	$(Q)$(CXX) $(CPPFLAGS) $(CXXFLAGS) $(SAN_FLAGS) -MMD -MP -c $< -o $@

$(BUILD)/small/%.o: %.cpp $(FLAGS_STAMP)
	$(call step,$< (small device))
	$(Q)$(CXX) $(CPPFLAGS) $(CXXFLAGS) $(SMALL_FLAGS) -MMD -MP -c $< -o $@

$(BUILD)/fuzzobj/%.o: %.cpp $(FLAGS_STAMP)
	$(call step,$< (fuzzing))
	$(Q)$(FUZZ_CXX) $(CPPFLAGS) $(FUZZ_FLAGS) -fsanitize=fuzzer-no-link -MMD -MP -c $< -o $@

# ---- install: headers, static library, the shitsukan tool, pkg-config file, CMake package;
# needs only a compiler (tools/install.sh) ----
install:
	@$(SUBMAKE) $(LIBRARY) $(CLI)
	@DESTDIR='$(DESTDIR)' bash tools/install.sh $(PREFIX) $(LIBRARY) $(CLI)

clean:
	rm -rf $(BUILD) paper_figures/out

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)

# ---- web port (ports/web): make web | test-wasm | test-web | bench-web, all in one file ----
include ports/web/web.mk
# ---- microcontrollers (ports/cortex-m): make test-mcu | bench-mcu | footprint-mcu, in one file ----
include ports/cortex-m/mcu.mk
