# shitsukan — plain Makefile (GNU make). See README.md.
#
#   make figures   install missing packages, build, render every paper figure
#   make test      install missing packages, build and run the tests
#   make all | test-sanitize | examples | bench | check-small | install PREFIX=... | deps | clean
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

# DESIGN.md: same inputs, same bits -> no FMA contraction, no fast-math.
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
SMALL_FLAGS := -fno-exceptions -fno-rtti -DSHITSUKAN_SMALL_DEVICE

LIB_SRCS     := $(shell find lib -name '*.cpp' 2>/dev/null | LC_ALL=C sort)
FIG_SRCS     := $(shell find paper_figures -name '*.cpp' -not -path 'paper_figures/out/*' 2>/dev/null | LC_ALL=C sort)
TEST_SRCS    := $(sort $(wildcard tests/*.cpp))
BENCH_SRCS   := $(sort $(wildcard tests/bench/*.cpp))
EXAMPLE_SRCS := $(sort $(wildcard examples/*.cpp))
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
SAN_OBJS   := $(LIB_SRCS:%.cpp=$(BUILD)/san/%.o) $(TEST_SRCS:%.cpp=$(BUILD)/san/%.o)
SMALL_OBJS := $(SMALL_SRCS:%.cpp=$(BUILD)/small/%.o)
EXAMPLES   := $(EXAMPLE_SRCS:examples/%.cpp=$(BUILD)/examples/%)
LIBRARY    := $(BUILD)/libshitsukan.a

.PHONY: all test test-sanitize figures examples bench check-small install deps bench-deps clean \
        fuzz fuzz-deps figures-determinism

# The top-level targets run one at a time (each builds in parallel inside its own sub-make), so
# `make -j test figures` cannot build the library twice at once.
SUBMAKE := $(MAKE) --no-print-directory SHITSUKAN_SUBMAKE=1 -j$(JOBS)
ifndef SHITSUKAN_SUBMAKE
.NOTPARALLEL:
endif

all: deps
	@$(SUBMAKE) $(LIBRARY) $(EXAMPLES) $(BUILD)/paper_figures

# ---- packages: installed when missing (apt-get as root), otherwise named ----
REQUIRED := /usr/include/doctest/doctest.h:doctest-dev /usr/include/stb/stb_image_write.h:libstb-dev
BENCH_REQUIRED := /usr/include/libnoise/noise.h:libnoise-dev /usr/include/boost/polygon/voronoi.hpp:libboost-dev \
                  /usr/include/CGAL/Delaunay_triangulation_2.h:libcgal-dev
define ensure_packages
	@missing=""; for pair in $(1); do f=$${pair%%:*}; p=$${pair##*:}; \
	  [ -f "$$f" ] || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then \
	    echo "shitsukan: installing$$missing (apt-get)"; \
	    apt-get update -qq >/dev/null && \
	    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null || \
	    { echo "shitsukan: apt-get install$$missing failed"; exit 1; }; \
	  else echo "shitsukan: missing packages:$$missing -- run: sudo apt-get install$$missing"; exit 1; fi; \
	fi
endef

deps:
	$(call ensure_packages,$(REQUIRED))

bench-deps: deps
	$(call ensure_packages,$(BENCH_REQUIRED))

# ---- fuzzing: libFuzzer harnesses (clang, ASan + UBSan) over the public entry points ----
# `make fuzz` builds fuzz/fuzz_*.cpp against the library compiled with the sanitizers, then
# runs each harness for FUZZ_SECONDS from its committed seed corpus (fuzz/corpus/<name>/) and
# fails on any finding (the input is saved as $(BUILD)/fuzz/crash-*). New interesting inputs
# go to $(BUILD)/fuzz/corpus-<name>/, not into the repository.
FUZZ_REQUIRED := /usr/bin/clang++:clang
FUZZ_CXX     ?= clang++
FUZZ_SECONDS ?= 20
FUZZ_FLAGS   := -std=c++17 -O1 -g -fno-omit-frame-pointer -ffp-contract=off \
                -fsanitize=address,undefined -fno-sanitize-recover=all
FUZZ_SRCS    := $(sort $(wildcard fuzz/fuzz_*.cpp))
FUZZERS      := $(FUZZ_SRCS:fuzz/%.cpp=$(BUILD)/fuzz/%)
FUZZ_OBJS    := $(LIB_SRCS:%.cpp=$(BUILD)/fuzzobj/%.o)

fuzz-deps:
	$(call ensure_packages,$(FUZZ_REQUIRED))

fuzz: fuzz-deps
	@$(SUBMAKE) $(FUZZERS)
	@for f in $(FUZZERS); do name=$$(basename $$f); \
	  mkdir -p $(BUILD)/fuzz/corpus-$$name; \
	  log=$(BUILD)/fuzz/$$name.log; \
	  if ! $$f -max_total_time=$(FUZZ_SECONDS) -timeout=1 -rss_limit_mb=2048 -print_final_stats=1 \
	       -artifact_prefix=$(BUILD)/fuzz/ $(BUILD)/fuzz/corpus-$$name fuzz/corpus/$$name \
	       > $$log 2>&1; then \
	    tail -40 $$log; echo "fuzz: $$name FOUND A DEFECT (input saved under $(BUILD)/fuzz/)"; exit 1; fi; \
	  runs=$$(sed -n 's/^stat::number_of_executed_units: *//p' $$log); \
	  echo "fuzz: $$name: $$runs executions in $(FUZZ_SECONDS) s, no finding"; \
	done

$(BUILD)/fuzz/%: fuzz/%.cpp fuzz/fuzz_input.hpp $(FUZZ_OBJS)
	@mkdir -p $(@D)
	$(FUZZ_CXX) $(CPPFLAGS) $(FUZZ_FLAGS) -fsanitize=fuzzer -o $@ $< $(FUZZ_OBJS)

$(BUILD)/fuzzobj/%.o: %.cpp $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(FUZZ_CXX) $(CPPFLAGS) $(FUZZ_FLAGS) -MMD -MP -c $< -o $@

# ---- determinism: the quick figures from g++ and from clang++ must be the same files ----
# (images, SVG, CSV, OBJ; the .md notes and tables carry measured times and are not compared)
figures-determinism: deps fuzz-deps
	@$(SUBMAKE) $(BUILD)/paper_figures
	@$(MAKE) --no-print-directory SHITSUKAN_SUBMAKE=1 -j$(JOBS) BUILD=$(BUILD)/clang CXX=clang++ CI= \
	  $(BUILD)/clang/paper_figures
	@rm -rf $(BUILD)/det-gcc $(BUILD)/det-clang
	$(BUILD)/paper_figures --quick --out $(BUILD)/det-gcc > /dev/null
	$(BUILD)/clang/paper_figures --quick --out $(BUILD)/det-clang > /dev/null
	@cd $(BUILD)/det-gcc && find . -type f ! -name '*.md' | LC_ALL=C sort | xargs sha256sum > ../det-gcc.sha
	@cd $(BUILD)/det-clang && find . -type f ! -name '*.md' | LC_ALL=C sort | xargs sha256sum > ../det-clang.sha
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

# Small-device core: compile with -fno-exceptions -fno-rtti, refuse any allocation, and refuse
# headers that bring in std containers or strings (a microcontroller toolchain may lack them).
check-small: $(SMALL_OBJS)
	@bad=$$(nm -C --undefined-only $(SMALL_OBJS) 2>/dev/null | \
	  grep -E ' (operator new|operator delete|malloc|calloc|realloc|free|__cxa_throw|__cxa_allocate_exception)' | sort -u); \
	if [ -n "$$bad" ]; then echo "check-small: allocation or exceptions in small-device files:"; echo "$$bad"; exit 1; fi; \
	for f in $(SMALL_SRCS); do \
	  h=$$($(CXX) $(CPPFLAGS) -std=c++17 -M $$f | tr ' ' '\n' | \
	      grep -E '/bits/(stl_vector|basic_string|unique_ptr|stl_map|stl_list|stl_deque|hashtable)\.h' | sort -u); \
	  if [ -n "$$h" ]; then echo "check-small: $$f includes host containers:"; echo "$$h"; exit 1; fi; \
	done; \
	echo "check-small: $(words $(SMALL_OBJS)) files compile with -fno-exceptions -fno-rtti, allocate nothing"; \
	echo "check-small: and include no std containers or strings (not even through headers)"

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
$(BUILD)/paper_figures: $(FIG_OBJS) $(LIBRARY)
	$(CXX) $(CXXFLAGS) -o $@ $(FIG_OBJS) $(LIBRARY)

$(BUILD)/bench: $(BENCH_OBJS) $(LIBRARY)
	$(CXX) $(CXXFLAGS) -o $@ $(BENCH_OBJS) $(LIBRARY) -lnoise -lmpfr -lgmp

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

# ---- install: headers, static library, pkg-config file ----
install: all
	@mkdir -p $(DESTDIR)$(PREFIX)/include $(DESTDIR)$(PREFIX)/lib/pkgconfig
	cd lib && find shitsukan -name '*.hpp' -exec install -D -m 644 {} $(DESTDIR)$(PREFIX)/include/{} \;
	install -m 644 $(LIBRARY) $(DESTDIR)$(PREFIX)/lib/libshitsukan.a
	@printf 'prefix=%s\nincludedir=$${prefix}/include\nlibdir=$${prefix}/lib\n\nName: shitsukan\nDescription: natural-material textures from five Japanese CG papers\nVersion: %s\nCflags: -I$${includedir} -std=c++17\nLibs: -L$${libdir} -lshitsukan\n' \
	  '$(PREFIX)' "$$(sed -n 's/.*VERSION_STRING "\(.*\)"/\1/p' lib/shitsukan/core/config.hpp)" \
	  > $(DESTDIR)$(PREFIX)/lib/pkgconfig/shitsukan.pc
	@echo "installed into $(DESTDIR)$(PREFIX)"

clean:
	rm -rf $(BUILD) paper_figures/out

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
