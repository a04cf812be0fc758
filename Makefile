# shitsukan — plain Makefile (GNU make). See README.md.
#
#   make figures   install missing packages, build, render every paper figure
#   make test      install missing packages, build and run the tests
#   make all | test-sanitize | examples | bench | check-small | install PREFIX=... | deps | clean
#   make measurements  runs the bench, keeps its output (docs/bench_output.txt) and generates
#                  docs/MEASUREMENTS.md from it (tools/bench_measurements.py)
#   make cli       the `shitsukan` command-line tool (build/shitsukan; cli/); make test-cli runs it
#   make check-api        headers compile alone, umbrella header complete, only shitsukan
#                         symbols exported, a program with its own stb links, PNGs without
#                         the stb header, dropped Status is a compile error under -Werror,
#                         README's module map matches the tree, required outputs are
#                         references (tools/check_output_params.py)
#   make check-manuals    every header's manual example compiles (and runs, unless compile-only)
#   make check-lengths    no function in lib/ over 100 lines (tools/function_lengths.py)
#   make check-references nothing cites an issue or a file outside the repository
#   make test-consumers   installs cmake/pkg-config if missing; builds tests/consumer four ways
#                         (add_subdirectory, FetchContent, find_package, pkg-config)
#   make test-mcu         installs the Arm toolchain, newlib and QEMU if missing; runs
#                         ports/cortex-m's transcript on the host, a Cortex-M4F and a Cortex-M7
#                         (QEMU mps2-an386 / mps2-an500) and requires identical transcripts
#
# Sources are discovered: any lib/shitsukan/**/*.cpp is part of the library, any
# paper_figures/**/*.cpp part of the figures driver, tests/*.cpp part of the test runner,
# tests/bench/*.cpp part of the benchmark, examples/NN_name.cpp one example each.

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
# check-small's stack budget per function (bytes, from -fstack-usage; chosen: a quarter of the
# 16 KB main stack ports/cortex-m reserves, so a call chain of a few library frames fits).
# Known over it, listed rather than hidden: none (incircle_exact's 37.8 KB of expansion
# arithmetic became a 2048-bit fixed-point sum of 1.1 KB).
empty :=
space := $(empty) $(empty)
STACK_BUDGET := 4096
STACK_OVER_BUDGET_KNOWN :=
STACK_KNOWN_RE := $(if $(strip $(STACK_OVER_BUDGET_KNOWN)),$(subst $(space),|,$(strip $(STACK_OVER_BUDGET_KNOWN))),no-function-is-a-known-exception)
# C library calls that may allocate (stdio buffers, printf's float and wide paths in newlib) or
# pull stdio into a firmware. Status messages use core/format_number (no printf) and the
# default assert handler traps under SHITSUKAN_SMALL_DEVICE (no fprintf/abort); IST digit
# labels too (format_integer). Known users, listed rather than hidden: none.
STDIO_CALLS := v?sn?printf|v?fprintf|printf|puts|fputs|fopen|fwrite|fflush|strdup|strndup|stderr|stdout|abort
STDIO_KNOWN :=
STDIO_KNOWN_RE := $(if $(strip $(STDIO_KNOWN)),$(subst $(space),|,$(strip $(STDIO_KNOWN))):,no-object-is-a-known-exception)

LIB_SRCS     := $(shell find lib -name '*.cpp' 2>/dev/null | LC_ALL=C sort)
FIG_SRCS     := $(shell find paper_figures -name '*.cpp' -not -path 'paper_figures/out/*' 2>/dev/null | LC_ALL=C sort)
TEST_SRCS    := $(sort $(wildcard tests/*.cpp))
BENCH_SRCS   := $(sort $(wildcard tests/bench/*.cpp))
EXAMPLE_SRCS := $(sort $(wildcard examples/*.cpp))
CLI_SRCS     := $(sort $(wildcard cli/*.cpp))
# Files that promise the small-device rules (no allocation, no exceptions) carry the line
# "// small-device: yes"; `make check-small` holds them to it.
SMALL_SRCS   := $(shell grep -rl '^// small-device: yes' lib 2>/dev/null | LC_ALL=C sort)

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
        check-references \
        install deps bench-deps consumer-deps mcu-deps clean fuzz fuzz-deps figures-determinism \
        cli test-cli test-mcu bench-mcu footprint-mcu check-manuals check-lengths measurements

# The top-level targets run one at a time (each builds in parallel inside its own sub-make), so
# `make -j test figures` cannot build the library twice at once.
SUBMAKE := $(MAKE) --no-print-directory SHITSUKAN_SUBMAKE=1 -j$(JOBS)
ifndef SHITSUKAN_SUBMAKE
.NOTPARALLEL:
endif

all: deps
	@$(SUBMAKE) $(LIBRARY) $(EXAMPLES) $(BUILD)/paper_figures $(CLI)

cli:
	@$(SUBMAKE) $(CLI)

# The tool's tests run the binary: good runs make their files, each bad flag exits 2 with a
# one-line message naming it (tests/cli/run.sh); failed writes (disk full, read-only or missing
# directories, a signal mid-write) leave nothing behind and name the reason (tests/cli/faults.sh).
test-cli: deps
	$(call ensure_packages,$(CLI_REQUIRED))
	@$(SUBMAKE) $(CLI)
	bash tests/cli/run.sh $(CLI)
	bash tests/cli/faults.sh $(CLI)

# ---- packages: installed when missing (apt-get as root), otherwise named ----
REQUIRED := /usr/include/doctest/doctest.h:doctest-dev /usr/include/stb/stb_image_write.h:libstb-dev
BENCH_REQUIRED := /usr/include/libnoise/noise.h:libnoise-dev /usr/include/boost/polygon/voronoi.hpp:libboost-dev \
                  /usr/include/CGAL/Surface_mesh.h:libcgal-dev /usr/include/CGAL/Delaunay_triangulation_2.h:libcgal-dev
# The checks written in Python (tools/*.py: module map, manual snippets, function lengths).
PY_REQUIRED := /usr/bin/python3:python3
# test-cli reads the tool's EXR maps back through an independent reader (tests/cli/exr_readback.py).
CLI_REQUIRED := /usr/share/doc/python3-openimageio/copyright:python3-openimageio /usr/share/doc/python3-numpy/copyright:python3-numpy
CONSUMER_REQUIRED := /usr/bin/cmake:cmake /usr/bin/pkg-config:pkg-config /usr/bin/git:git
define ensure_packages
	@missing=""; for pair in $(1); do f=$${pair%%:*}; p=$${pair##*:}; \
	  [ -f "$$f" ] || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then \
	    echo "shitsukan: installing$$missing (apt-get)"; \
	    apt-get -o DPkg::Lock::Timeout=600 update -qq >/dev/null && \
	    DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -qq $$missing >/dev/null || \
	    { echo "shitsukan: apt-get install$$missing failed"; exit 1; }; \
	  else echo "shitsukan: missing packages:$$missing -- run: sudo apt-get install$$missing"; exit 1; fi; \
	fi
endef

deps:
	$(call ensure_packages,$(REQUIRED))

bench-deps: deps
	$(call ensure_packages,$(BENCH_REQUIRED))

consumer-deps: deps
	$(call ensure_packages,$(CONSUMER_REQUIRED))

# ---- fuzzing: libFuzzer harnesses (clang, ASan + UBSan) over the public entry points ----
# `make fuzz` builds fuzz/fuzz_*.cpp against the library compiled with the sanitizers, then
# runs each harness for FUZZ_SECONDS from its committed seed corpus (fuzz/corpus/<name>/) and
# fails on any finding (the input is saved as $(BUILD)/fuzz/crash-*). New interesting inputs
# go to $(BUILD)/fuzz/corpus-<name>/, not into the repository.
FUZZ_REQUIRED := /usr/bin/clang++:clang
FUZZ_CXX     ?= clang++
FUZZ_SECONDS ?= 20
# A fixed libFuzzer seed keeps CI's short runs reproducible; FUZZ_SEED=0 picks a random one.
FUZZ_SEED    ?= 1
# 1: a new finding in the timed exploration fails the target. CI uses 0 while fuzz/findings/
# holds an open finding (the committed corpus replay always fails on a regression).
FUZZ_STRICT  ?= 1
# Per-input timeout in seconds, for the replay and the exploration. libFuzzer's is wall-clock
# time, so a loaded machine stretches it: a committed input needing 0.20 s of CPU took 1.43 s
# under load and failed the replay at the old 1 s; at nice 19 under a load of 12 on 2 cores,
# inputs of 0.04-0.19 s of CPU took 10-31 s of wall clock. Chosen here: 120 s, about 600
# times the slowest committed input's CPU time (0.11-0.19 s for a whole process, measured),
# so load cannot trip it, while a real hang (an endless loop) still fails the run.
FUZZ_TIMEOUT ?= 120
FUZZ_FLAGS   := -std=c++17 -O1 -g -fno-omit-frame-pointer -ffp-contract=off \
                -fsanitize=address,undefined -fno-sanitize-recover=all
FUZZ_SRCS    := $(sort $(wildcard fuzz/fuzz_*.cpp))
FUZZERS      := $(FUZZ_SRCS:fuzz/%.cpp=$(BUILD)/fuzz/%)
FUZZ_OBJS    := $(LIB_SRCS:%.cpp=$(BUILD)/fuzzobj/%.o)
# kept between runs (only prerequisites of the pattern rule below, make would delete them);
# compiled with libFuzzer's coverage (fuzzer-no-link) so that it guides into the library
.SECONDARY: $(FUZZ_OBJS)

fuzz-deps:
	$(call ensure_packages,$(FUZZ_REQUIRED))

fuzz: fuzz-deps
	@$(SUBMAKE) $(FUZZERS)
	@for f in $(FUZZERS); do name=$$(basename $$f); \
	  log=$(BUILD)/fuzz/$$name.replay.log; \
	  if ! $$f -runs=0 -timeout=$(FUZZ_TIMEOUT) -rss_limit_mb=2048 fuzz/corpus/$$name > $$log 2>&1; then \
	    tail -40 $$log; echo "fuzz: $$name FAILS ON ITS COMMITTED CORPUS (a regression)"; exit 1; fi; \
	  echo "fuzz: $$name: committed corpus ($$(ls fuzz/corpus/$$name | wc -l) inputs) replayed clean"; \
	done
	@found=0; for f in $(FUZZERS); do name=$$(basename $$f); \
	  mkdir -p $(BUILD)/fuzz/corpus-$$name; \
	  log=$(BUILD)/fuzz/$$name.log; \
	  if ! $$f -seed=$(FUZZ_SEED) -max_total_time=$(FUZZ_SECONDS) -timeout=$(FUZZ_TIMEOUT) -rss_limit_mb=2048 -print_final_stats=1 \
	       -artifact_prefix=$(BUILD)/fuzz/ $(BUILD)/fuzz/corpus-$$name fuzz/corpus/$$name \
	       > $$log 2>&1; then \
	    grep -m1 "contract broken\|ERROR" $$log; \
	    echo "fuzz: $$name FOUND A DEFECT (input saved under $(BUILD)/fuzz/)"; found=1; continue; fi; \
	  runs=$$(sed -n 's/^stat::number_of_executed_units: *//p' $$log); \
	  echo "fuzz: $$name: $$runs executions in $(FUZZ_SECONDS) s, no finding"; \
	done; \
	if [ $$found = 1 ] && [ "$(FUZZ_STRICT)" = 1 ]; then exit 1; fi; \
	if [ $$found = 1 ]; then echo "fuzz: findings reported, not failing (FUZZ_STRICT=0: open findings in fuzz/findings/)"; fi

$(BUILD)/fuzz/%: fuzz/%.cpp fuzz/fuzz_input.hpp $(FUZZ_OBJS)
	@mkdir -p $(@D)
	$(FUZZ_CXX) $(CPPFLAGS) $(FUZZ_FLAGS) -fsanitize=fuzzer -o $@ $< $(FUZZ_OBJS)

# stb_image (compiled inside image_read.cpp) hands memcpy a null pointer for an empty IDAT chunk
# (0 bytes: harmless, but UBSan's nonnull-attribute check stops there; found by fuzz_readers).
# That one check is off for that one file; every other check stays on, in it too.
$(BUILD)/fuzzobj/lib/shitsukan/image/image_read.o: FUZZ_FLAGS += -fno-sanitize=nonnull-attribute

$(BUILD)/fuzzobj/%.o: %.cpp $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(FUZZ_CXX) $(CPPFLAGS) $(FUZZ_FLAGS) -fsanitize=fuzzer-no-link -MMD -MP -c $< -o $@

# ---- determinism: the quick figures from g++ and from clang++ must be the same files ----
# (images, SVG, CSV, OBJ; the .md notes and tables carry measured times and are not compared)
# The g++ figures are rendered twice, on 2 threads and on 1 (--jobs): the same files again,
# and the same index apart from measured numbers (headings, outputs and parameter rows).
DET_INDEX_LINES := grep -E '^(\#|!\[|Output:)|\| (given|chosen here) \| [^|]*\|$$'
figures-determinism: deps fuzz-deps
	@$(SUBMAKE) $(BUILD)/paper_figures
	@$(MAKE) --no-print-directory SHITSUKAN_SUBMAKE=1 -j$(JOBS) BUILD=$(BUILD)/clang CXX=clang++ CI= \
	  $(BUILD)/clang/paper_figures
	@rm -rf $(BUILD)/det-gcc $(BUILD)/det-gcc-j1 $(BUILD)/det-clang
	$(BUILD)/paper_figures --quick --jobs 2 --out $(BUILD)/det-gcc > /dev/null
	$(BUILD)/paper_figures --quick --jobs 1 --out $(BUILD)/det-gcc-j1 > /dev/null
	$(BUILD)/clang/paper_figures --quick --out $(BUILD)/det-clang > /dev/null
	@for d in det-gcc det-gcc-j1 det-clang; do \
	  (cd $(BUILD)/$$d && find . -type f ! -name '*.md' | LC_ALL=C sort | xargs sha256sum > ../$$d.sha \
	   && $(DET_INDEX_LINES) index.md > ../$$d.index) || exit 1; done
	@if diff $(BUILD)/det-gcc.sha $(BUILD)/det-gcc-j1.sha > $(BUILD)/det.diff && \
	  diff $(BUILD)/det-gcc.index $(BUILD)/det-gcc-j1.index >> $(BUILD)/det.diff; then \
	  echo "figures-determinism: $$(wc -l < $(BUILD)/det-gcc.sha) files and $$(wc -l < $(BUILD)/det-gcc.index) index lines identical with --jobs 2 and --jobs 1"; \
	else echo "figures-determinism: --jobs 2 and --jobs 1 outputs differ:"; cat $(BUILD)/det.diff; exit 1; fi
	@if diff $(BUILD)/det-gcc.sha $(BUILD)/det-clang.sha > $(BUILD)/det.diff; then \
	  echo "figures-determinism: $$(wc -l < $(BUILD)/det-gcc.sha) files identical between g++ and clang++"; \
	else echo "figures-determinism: g++ and clang++ outputs differ:"; cat $(BUILD)/det.diff; exit 1; fi

# ---- the two set-up commands ----
test: deps
	@$(SUBMAKE) $(BUILD)/tests
	$(BUILD)/tests

figures: deps
	@$(SUBMAKE) $(BUILD)/paper_figures
	$(BUILD)/paper_figures $(FIGURES_ARGS)

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

# The measured numbers of docs/MEASUREMENTS.md (which README links): the bench's output is kept
# as docs/bench_output.txt and the page generated from it by tools/bench_measurements.py, never
# typed. MEASUREMENTS_FROM=<saved output> regenerates the page without running the bench.
MEASUREMENTS_FROM ?=
measurements: bench-deps
	$(call ensure_packages,$(PY_REQUIRED))
ifeq ($(MEASUREMENTS_FROM),)
	@$(SUBMAKE) $(BUILD)/bench
	$(BUILD)/bench $(BENCH_ARGS) > $(BUILD)/bench_output.txt
	cp $(BUILD)/bench_output.txt docs/bench_output.txt
	python3 tools/bench_measurements.py docs/bench_output.txt docs/MEASUREMENTS.md
else
	python3 tools/bench_measurements.py $(MEASUREMENTS_FROM) docs/MEASUREMENTS.md
endif

# Small-device core: compile with -fno-exceptions -fno-rtti, refuse any allocation, and refuse
# headers that bring in std containers or strings (a microcontroller toolchain may lack them).
check-small: $(SMALL_OBJS)
	@bad=$$(nm -C --undefined-only $(SMALL_OBJS) 2>/dev/null | \
	  grep -E ' (operator new|operator delete|malloc|calloc|realloc|free|__cxa_throw|__cxa_allocate_exception)' | sort -u); \
	if [ -n "$$bad" ]; then echo "check-small: allocation or exceptions in small-device files:"; echo "$$bad"; exit 1; fi; \
	stdio=$$(nm -A --undefined-only $(SMALL_OBJS) 2>/dev/null | grep -E ' U ($(STDIO_CALLS))$$' | \
	  grep -v -E '$(STDIO_KNOWN_RE)' || true); \
	if [ -n "$$stdio" ]; then echo "check-small: C library calls that may allocate or pull in stdio:"; echo "$$stdio"; exit 1; fi; \
	for f in $(SMALL_SRCS); do \
	  h=$$($(CXX) $(CPPFLAGS) -std=c++17 -M $$f | tr ' ' '\n' | \
	      grep -E '/bits/(stl_vector|basic_string|unique_ptr|stl_map|stl_list|stl_deque|hashtable)\.h' | sort -u); \
	  if [ -n "$$h" ]; then echo "check-small: $$f includes host containers:"; echo "$$h"; exit 1; fi; \
	done; \
	for h in $(SMALL_HPPS:lib/%=%); do printf '#include "%s"\n' "$$h" | \
	  $(CXX) $(CPPFLAGS) $(CXXFLAGS) $(filter-out -fstack-usage,$(SMALL_FLAGS)) -fsyntax-only -x c++ - || \
	  { echo "check-small: header $$h does not compile alone under the small-device flags"; exit 1; }; done; \
	su=$$(cat $(SMALL_OBJS:.o=.su)); \
	unbounded=$$(printf '%s\n' "$$su" | awk -F'\t' '$$3 ~ /dynamic/ && $$3 !~ /bounded/'); \
	if [ -n "$$unbounded" ]; then echo "check-small: unbounded stack (VLA/alloca):"; echo "$$unbounded"; exit 1; fi; \
	over=$$(printf '%s\n' "$$su" | awk -F'\t' -v b=$(STACK_BUDGET) '$$2 > b' | grep -v -E '$(STACK_KNOWN_RE)' || true); \
	if [ -n "$$over" ]; then echo "check-small: functions over the $(STACK_BUDGET)-byte stack budget:"; echo "$$over"; exit 1; fi; \
	deepest=$$(printf '%s\n' "$$su" | grep -v -E '$(STACK_KNOWN_RE)' | sort -t'	' -k2 -n -r | head -1 | awk -F'\t' '{ print $$2 " bytes: " $$1 }'); \
	known=$$(printf '%s\n' "$$su" | grep -E '$(STACK_KNOWN_RE)' | awk -F'\t' '{ print $$2 " bytes: " $$1 }'); \
	echo "check-small: $(words $(SMALL_CPPS)) small-device .cpp files compile with -fno-exceptions -fno-rtti -Wdouble-promotion and allocate nothing;"; \
	echo "check-small: all $(words $(SMALL_SRCS)) small-device files ($(words $(SMALL_CPPS)) .cpp, $(words $(SMALL_HPPS)) headers) include no std containers or strings; the $(words $(SMALL_HPPS)) headers compile alone under the same flags"; \
	echo "check-small: stack per function <= $(STACK_BUDGET) bytes (-fstack-usage), deepest $$deepest"; \
	$(if $(strip $(STACK_OVER_BUDGET_KNOWN)),echo "check-small: KNOWN over budget: $$known";,true;) \
	echo "check-small: no stdio or allocating C library call ($(STDIO_CALLS))$(if $(strip $(STDIO_KNOWN)), outside the KNOWN users $(STDIO_KNOWN))"

# Using the library from outside: see check-api / test-consumers in the header of this file.
HEADERS := $(shell find lib -name '*.hpp' 2>/dev/null | LC_ALL=C sort)
API_DIR := $(BUILD)/api
check-api: deps
	$(call ensure_packages,$(PY_REQUIRED))
	@$(SUBMAKE) $(LIBRARY)
	@mkdir -p $(API_DIR)
	@# 1. every header compiles on its own (it includes what it uses)
	@printf '%s\n' $(HEADERS:lib/%=%) | xargs -P $(JOBS) -I{} sh -c \
	  'printf "#include \"%s\"\n" "{}" | $(CXX) $(CXXFLAGS) -Ilib -fsyntax-only -x c++ - || \
	   { echo "check-api: {} does not compile alone"; exit 255; }'
	@echo "check-api: $(words $(HEADERS)) headers compile alone"
	@# 2. the umbrella header includes every header (tools/gen_umbrella.sh writes it)
	@missing=$$(for h in $(filter-out lib/shitsukan/shitsukan.hpp,$(HEADERS)); do \
	  grep -qF "#include \"$${h#lib/}\"" lib/shitsukan/shitsukan.hpp || echo "$${h#lib/}"; done); \
	if [ -n "$$missing" ]; then echo "check-api: shitsukan/shitsukan.hpp misses (run tools/gen_umbrella.sh):"; \
	  echo "$$missing"; exit 1; fi; echo "check-api: shitsukan/shitsukan.hpp includes all of them"
	@# 3. the archive exports only shitsukan symbols (std:: template instances are weak, shared)
	@bad=$$(nm -g --defined-only $(LIBRARY) | awk 'NF == 3 { print $$2, $$3 }' | \
	  awk '($$1 ~ /^[TDBRGSC]$$/ && $$2 !~ /9shitsukan/) || ($$1 ~ /^[WVu]$$/ && $$2 !~ /9shitsukan/ && \
	       $$2 !~ /^(_ZN?K?St|_ZN?K?9__gnu_cxx|_ZT[ISV]N?St|DW\.ref\.__gxx_personality_v0$$)/) \
	       { print $$2 }' | sort -u); \
	if [ -n "$$bad" ]; then echo "check-api: libshitsukan.a exports symbols outside namespace shitsukan:"; \
	  echo "$$bad" | c++filt | head -20; exit 1; fi
	@echo "check-api: libshitsukan.a exports only shitsukan symbols (no stbi_*)"
	@# 4. a program with its own stb_image_write implementation links and runs
	$(CXX) $(CPPFLAGS) -std=c++17 -O1 -w tests/consumer/stb_clash.cpp $(LIBRARY) -o $(API_DIR)/stb_clash
	@$(API_DIR)/stb_clash $(API_DIR)/own.png $(API_DIR)/ours.png
	@# 4b. built without the stb header (as `make install` on a bare machine), PNGs still work
	$(CXX) $(CXXFLAGS) -DSHITSUKAN_NO_STB -Ilib -c lib/shitsukan/image/image_io.cpp -o $(API_DIR)/image_io_nostb.o
	$(CXX) $(CXXFLAGS) -Ilib tests/consumer/png_without_stb.cpp $(API_DIR)/image_io_nostb.o $(LIBRARY) \
	  -o $(API_DIR)/png_without_stb
	@$(API_DIR)/png_without_stb $(API_DIR)/nostb.png
	@# 5. a dropped Status is a compile error under -Werror (and the checked form compiles)
	@$(CXX) $(CPPFLAGS) -std=c++17 -Wall -Werror -DSHITSUKAN_CHECKED -fsyntax-only \
	  tests/compile_fail/dropped_status.cpp || { echo "check-api: the checked form does not compile"; exit 1; }
	@if $(CXX) $(CPPFLAGS) -std=c++17 -Wall -Werror -fsyntax-only tests/compile_fail/dropped_status.cpp \
	     2> $(API_DIR)/dropped_status.log; then \
	  echo "check-api: dropping a Status compiled under -Werror"; exit 1; fi; \
	grep -q "nodiscard" $(API_DIR)/dropped_status.log || \
	  { echo "check-api: dropped_status.cpp failed, but not for nodiscard:"; cat $(API_DIR)/dropped_status.log; exit 1; }
	@echo "check-api: a dropped Status does not compile under -Werror (nodiscard)"
	@# 6. README.md's module map lists what the tree holds, and nothing else
	@python3 tools/check_module_map.py
	@# 7. required outputs are references, not pointers every function null-checks
	@python3 tools/check_output_params.py

# Every header's manual example (the lines under "// Manual") compiled into a program of its
# own against the library and, unless tagged "// Manual (compile-only)", run
# (tools/extract_manuals.py; sources and programs in build/manuals/).
check-manuals: deps
	$(call ensure_packages,$(PY_REQUIRED))
	@$(SUBMAKE) $(LIBRARY)
	@python3 tools/extract_manuals.py --build --out $(BUILD)/manuals --cxx '$(CXX)' \
	  --flags '$(CPPFLAGS) $(CXXFLAGS) -O0 -Wno-unused-variable -Wno-unused-but-set-variable' \
	  --lib $(LIBRARY) -j $(JOBS)

# No function in lib/ over 100 lines (tools/function_lengths.py lists the ones over).
check-lengths:
	$(call ensure_packages,$(PY_REQUIRED))
	@python3 tools/function_lengths.py lib

# Nothing cites an issue or a file outside the repository (tools/check_references.py).
check-references:
	$(call ensure_packages,$(PY_REQUIRED))
	@python3 tools/check_references.py

test-consumers: consumer-deps
	JOBS=$(JOBS) CXX=$(CXX) bash tests/consumer/run.sh

# ---- linking ----
$(LIBRARY): $(LIB_OBJS)
	@mkdir -p $(@D)
	@rm -f $@
	$(AR) rcs $@ $^

$(BUILD)/tests: $(TEST_OBJS) $(LIBRARY)
	$(CXX) $(CXXFLAGS) -o $@ $(TEST_OBJS) $(LIBRARY)

$(BUILD)/tests-sanitize: $(SAN_OBJS)
	$(CXX) $(CXXFLAGS) $(SAN_FLAGS) -o $@ $(SAN_OBJS)

# Figure objects are linked directly (not through an archive): they register themselves.
# -pthread: the driver renders figures on threads (--jobs).
$(BUILD)/paper_figures: $(FIG_OBJS) $(LIBRARY)
	$(CXX) $(CXXFLAGS) -pthread -o $@ $(FIG_OBJS) $(LIBRARY)

$(BUILD)/bench: $(BENCH_OBJS) $(LIBRARY)
	$(CXX) $(CXXFLAGS) -o $@ $(BENCH_OBJS) $(LIBRARY) -lnoise -lmpfr -lgmp

$(CLI): $(CLI_OBJS) $(LIBRARY)
	$(CXX) $(CXXFLAGS) -o $@ $(CLI_OBJS) $(LIBRARY)

$(BUILD)/examples/%: $(BUILD)/obj/examples/%.o $(LIBRARY)
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS) -o $@ $< $(LIBRARY)

# ---- compiling ----
$(FLAGS_STAMP):
	@mkdir -p $(@D)
	@rm -f $(BUILD)/.flags-*
	@touch $@

$(BUILD)/obj/%.o: %.cpp $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) $(CXXFLAGS) -MMD -MP -c $< -o $@

$(BUILD)/san/%.o: %.cpp $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) $(CXXFLAGS) $(SAN_FLAGS) -MMD -MP -c $< -o $@

$(BUILD)/small/%.o: %.cpp $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) $(CXXFLAGS) $(SMALL_FLAGS) -MMD -MP -c $< -o $@

# ---- install: headers, static library, the shitsukan tool, pkg-config file, CMake package ----
# Needs only a compiler: no test framework, no apt-get (without the stb header write_png
# uses the library's own, uncompressed PNG encoder). The version is core/config.hpp's.
VERSION := $(shell sed -n 's/^\#define SHITSUKAN_VERSION_STRING "\(.*\)"/\1/p' lib/shitsukan/core/config.hpp)
VERSION_MAJOR := $(word 1,$(subst ., ,$(VERSION)))
VERSION_MINOR := $(word 2,$(subst ., ,$(VERSION)))
install:
	@$(SUBMAKE) $(LIBRARY) $(CLI)
	@mkdir -p $(DESTDIR)$(PREFIX)/include $(DESTDIR)$(PREFIX)/lib/pkgconfig \
	  $(DESTDIR)$(PREFIX)/lib/cmake/shitsukan $(DESTDIR)$(PREFIX)/bin
	install -m 755 $(CLI) $(DESTDIR)$(PREFIX)/bin/shitsukan
	cd lib && find shitsukan -name '*.hpp' -exec install -D -m 644 {} $(DESTDIR)$(PREFIX)/include/{} \;
	install -m 644 $(LIBRARY) $(DESTDIR)$(PREFIX)/lib/libshitsukan.a
	sed -e 's|@SHITSUKAN_PC_PREFIX@|$(PREFIX)|' -e 's|@SHITSUKAN_PC_INCLUDEDIR@|$${prefix}/include|' \
	  -e 's|@SHITSUKAN_PC_LIBDIR@|$${prefix}/lib|' -e 's|@SHITSUKAN_PC_VERSION@|$(VERSION)|' \
	  cmake/shitsukan.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/shitsukan.pc
	install -m 644 cmake/shitsukanConfig-make.cmake.in \
	  $(DESTDIR)$(PREFIX)/lib/cmake/shitsukan/shitsukanConfig.cmake
	sed -e 's|@VERSION@|$(VERSION)|' -e 's|@MAJOR@|$(VERSION_MAJOR)|' -e 's|@MINOR@|$(VERSION_MINOR)|' \
	  cmake/shitsukanConfigVersion-make.cmake.in \
	  > $(DESTDIR)$(PREFIX)/lib/cmake/shitsukan/shitsukanConfigVersion.cmake
	@echo "installed shitsukan $(VERSION) into $(DESTDIR)$(PREFIX)"

clean:
	rm -rf $(BUILD) paper_figures/out

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)

# ---- web port (ports/web): make web | test-wasm | test-web | bench-web, all in one file ----
include ports/web/web.mk
# ---- end of the web port ----
# ---- microcontrollers (ports/cortex-m): make test-mcu | bench-mcu | footprint-mcu, in one file ----
include ports/cortex-m/mcu.mk
