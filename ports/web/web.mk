# ---- web: ports/web, the explorer (the five papers step by step in a browser, and a classroom bundle;
# ports/web/README.md). Included from the Makefile; everything of the web port is in this file.
#
#   make web        installs Debian's emscripten if missing; builds build/web/: index.html (one
#                   file, opens from disk by double-click) and build/web/hosted/ (index.html +
#                   shitsukan_web.js + .wasm + the page's files, for a static web server)
#   make test-wasm  the doctest suite compiled to WASM and run under node: every case passes, or
#                   is excluded by name with its reason printed (WASM_TEST_SKIPS below)
#   make test-web   the native reference of the page's self-test, then Debian's headless
#                   Chromium opens build/web/index.html from disk: the page's hashes must equal
#                   the native ones (PASS in the DOM), a slider must change picture and hash,
#                   and no panel may log a console error; the self-test again in Firefox ESR
#                   (WebDriver BiDi) and one panel drawn there at 1280x720; the web-dist zip
#                   unpacked and opened from disk (ports/web/tests/test_web.sh, test_dist.sh)
#   make web-dist   the classroom bundle: build/web-dist/ (index.html, sources/, a README for
#                   teachers from ports/web/dist/README.md) and build/web-dist.zip of the same
#                   (ports/web/dist/dist.py); opens from a USB stick (file://) or any static host
#   make bench-web  bench: lines (first panel ready, slider -> new 512x512 marble frame, an IST
#                   diagram redraw, a WR surface at fig. 14's size re-tessellated and drawn, the
#                   camphor run at 128 x 64 and its replay's frames per second, .wasm size raw
#                   and gzip) against the goals of ports/web/README.md
#
# Debian's emscripten works offline as shipped. Its linker runs node scripts that need acorn
# from Debian's node modules: NODE_PATH points there in case `node` is not Debian's.
WEB_REQUIRED := /usr/bin/em++:emscripten /usr/share/nodejs/acorn/package.json:node-acorn \
                /usr/bin/chromium:chromium /usr/bin/firefox-esr:firefox-esr /usr/bin/node:nodejs /usr/bin/python3:python3 /usr/bin/gzip:gzip
WEB_DIR      := $(BUILD)/web
EMXX         ?= em++
EM_ENV       := NODE_PATH=/usr/share/nodejs$(if $(NODE_PATH),:$(NODE_PATH))
# The papers whose figure parameter tables the page shows (paper_figures' own records).
WEB_PAPERS   := okada1987 okada1989 tokai1994
# fujimoto2000: the IST figures and Table 1 only (the surfaces' figures take minutes).
WEB_PAPERS   += fujimoto2000/fig03 fujimoto2000/fig04 fujimoto2000/fig06a fujimoto2000/fig06b \
                fujimoto2000/fig07 fujimoto2000/fig08 fujimoto2000/fig09 fujimoto2000/table01
# hirota1998: the two-layer model's figures (the species runs at the quick size).
WEB_PAPERS   += hirota1998/fig04 hirota1998/fig05 hirota1998/fig08 hirota1998/fig11
# fujimoto2000 WR surfaces: one panel each of figs. 14, 17, 18 for their parameter tables.
WEB_PAPERS   += fujimoto2000/fig14b fujimoto2000/fig17a4 fujimoto2000/fig18a5
# fujimoto2000 fig. 21's superposed terrain (the jitter's record).
WEB_PAPERS   += fujimoto2000/fig21f
# Same flags as the native build (docs/DESIGN.md: same inputs, same bits). stb's headers come
# from Debian's libstb-dev through a directory of their own (not all of /usr/include: the WASM
# build must not see glibc's headers), as system headers like the native build's; the page never reads or writes image files, so the
# linker drops them from the page.
WEB_CXXFLAGS := -std=c++17 -O2 $(WARN) -ffp-contract=off
WEB_CPPFLAGS := -Ilib -Ipaper_figures -Iports/web -isystem $(WEB_DIR)/include
WEB_API_SRCS := $(sort $(wildcard ports/web/api/*.cpp))
# The figures' code the panels share with paper_figures (the IST diagrams of figs. 3-9).
WEB_API_SRCS += paper_figures/fujimoto2000/ist_diagram.cpp
# ... fig. 21's terrain control mesh, fig. 11's 3D scene of the branch, fig. 8's frames.
WEB_API_SRCS += paper_figures/fujimoto2000/terrain_mesh.cpp paper_figures/hirota1998/branch_scene.cpp \
                paper_figures/hirota1998/layer_frame_draw.cpp
WEB_LIB_OBJS := $(LIB_SRCS:%.cpp=$(WEB_DIR)/obj/%.o)
WEB_API_OBJS := $(WEB_API_SRCS:%.cpp=$(WEB_DIR)/obj/%.o)
WEB_TEST_OBJS := $(TEST_SRCS:%.cpp=$(WEB_DIR)/obj/%.o)
WEB_PAGE_SRCS := $(sort $(wildcard ports/web/page/*.html ports/web/page/*.css ports/web/page/*.js \
                   ports/web/page/panels/*.js))
# A 2 GiB heap at most (WASM32's limit in Chromium), grown on demand.
WEB_LINK     := -O2 -sALLOW_MEMORY_GROWTH=1 -sMAXIMUM_MEMORY=2GB -sMODULARIZE=1 \
                -sEXPORT_NAME=createShitsukan -sEXPORTED_RUNTIME_METHODS=['UTF8ToString','HEAPU8'] \
                -sENVIRONMENT=web,worker -sFILESYSTEM=0
# The test runner under node: one file (the loader of emscripten 3.1.6 fails under node 20
# when it must fetch a separate .wasm), the host's files through NODERAWFS (tests/data, build/).
WEB_TEST_LINK := -O2 -sALLOW_MEMORY_GROWTH=1 -sMAXIMUM_MEMORY=2GB -sENVIRONMENT=node \
                 -sSINGLE_FILE=1 -sNODERAWFS=1 -sEXIT_RUNTIME=1 -sTOTAL_STACK=4MB
# Test cases that cannot run as WASM, each with its reason (printed by make test-wasm).
# Patterns are doctest's (wildcards; a comma would split them).
WASM_TEST_SKIPS := \
  "a refused*Status ignored aborts naming the call|no fork() in WASM: the test watches the abort from a parent process" \
  "a checked* successful build does not trip the check|no fork() in WASM: the test runs the build in a child process" \
  "*for %p (glibc's pointer text)|glibc's text for a null %p, (nil); emscripten's musl prints 0" \
  "output_file: a failed overwrite keeps the old file*|no setrlimit(RLIMIT_FSIZE) in WASM: the test fills the disk by a file-size limit" \
  "output_file: an OutputSet writes all its files or none|NODERAWFS (the test runner's file system) fails the set's hard-link back-ups and /dev/full differently; the page has no file system" \
  "output_file: SIGINT while a file is open*|no fork() in WASM: the test interrupts a child process"

# tests/test_core_status.cpp hands printf an int for %hhd on purpose (the Status formatter must
# convert as printf does); clang's -Wformat names it, g++ does not.
$(WEB_TEST_OBJS): WEB_EXTRA := -Wno-format

.PHONY: web web-dist web-screenshots test-wasm test-web bench-web web-deps

web-deps:
	$(call ensure_packages,$(WEB_REQUIRED) $(REQUIRED))

web: web-deps
	@$(SUBMAKE) $(WEB_DIR)/index.html $(WEB_DIR)/native_reference
	@echo "web: open $(WEB_DIR)/index.html (one file, from disk) or serve $(WEB_DIR)/hosted/"

$(WEB_DIR)/include/.stamp:
	@mkdir -p $(@D)
	@ln -sfn /usr/include/stb $(@D)/stb
	@ln -sfn /usr/include/doctest $(@D)/doctest
	@touch $@

# Objects depend on a stamp named after the WASM flags too (as the native build's FLAGS_STAMP).
WEB_FLAGS_HASH  := $(shell printf '%s' '$(EMXX) $(WEB_CPPFLAGS) $(WEB_CXXFLAGS)' | cksum | cut -d' ' -f1)
WEB_FLAGS_STAMP := $(WEB_DIR)/.flags-$(WEB_FLAGS_HASH)
$(WEB_FLAGS_STAMP):
	@mkdir -p $(@D)
	@rm -f $(WEB_DIR)/.flags-*
	@touch $@

$(WEB_DIR)/obj/%.o: %.cpp $(WEB_FLAGS_STAMP) $(WEB_DIR)/include/.stamp
	@mkdir -p $(@D)
	$(EM_ENV) $(EMXX) $(WEB_CPPFLAGS) $(WEB_CXXFLAGS) $(WEB_EXTRA) -MMD -MP -c $< -o $@

# The module: hosted (.js + .wasm) and single-file (the .wasm inside the .js, for file://).
$(WEB_DIR)/hosted/shitsukan_web.js: $(WEB_LIB_OBJS) $(WEB_API_OBJS)
	@mkdir -p $(@D)
	$(EM_ENV) $(EMXX) $(WEB_LINK) -o $@ $(WEB_API_OBJS) $(WEB_LIB_OBJS)

$(WEB_DIR)/single/shitsukan_web.js: $(WEB_LIB_OBJS) $(WEB_API_OBJS)
	@mkdir -p $(@D)
	$(EM_ENV) $(EMXX) $(WEB_LINK) -sSINGLE_FILE=1 -o $@ $(WEB_API_OBJS) $(WEB_LIB_OBJS)

# The figures' parameter tables, as paper_figures records them (never retyped).
$(WEB_DIR)/figures/index.md: $(BUILD)/paper_figures ports/web/web.mk
	@rm -rf $(WEB_DIR)/figures
	$(BUILD)/paper_figures --quick --jobs $(JOBS) $(WEB_PAPERS:%=--only %) --out $(WEB_DIR)/figures > /dev/null

# The bundle copies the source files the panels link to (sources/): any library file may be one.
$(WEB_DIR)/index.html: $(WEB_DIR)/hosted/shitsukan_web.js $(WEB_DIR)/single/shitsukan_web.js \
                       $(WEB_DIR)/figures/index.md $(WEB_PAGE_SRCS) ports/web/bundle.py \
                       $(WEB_API_SRCS) $(wildcard lib/shitsukan/*/*.hpp lib/shitsukan/*/*.cpp)
	python3 ports/web/bundle.py --page ports/web/page --figures $(WEB_DIR)/figures/index.md \
	  --hosted-module $(WEB_DIR)/hosted/shitsukan_web.js --single-module $(WEB_DIR)/single/shitsukan_web.js \
	  --out $(WEB_DIR)

$(WEB_DIR)/native_reference: ports/web/native_reference.cpp $(WEB_API_SRCS) ports/web/api/api_common.hpp \
                             ports/web/api/shitsukan_web.h $(LIBRARY)
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) -Iports/web $(CXXFLAGS) -o $@ ports/web/native_reference.cpp $(WEB_API_SRCS) $(LIBRARY)

$(WEB_DIR)/tests.js: $(WEB_TEST_OBJS) $(WEB_LIB_OBJS)
	$(EM_ENV) $(EMXX) $(WEB_TEST_LINK) -o $@ $(WEB_TEST_OBJS) $(WEB_LIB_OBJS)

WEB_DIST := $(BUILD)/web-dist
$(WEB_DIST).zip: $(WEB_DIR)/index.html ports/web/dist/dist.py ports/web/dist/README.md
	python3 ports/web/dist/dist.py --web $(WEB_DIR) --readme ports/web/dist/README.md \
	  --panels ports/web/page/panels --out $(WEB_DIST) --zip $@

web-dist: web
	@$(SUBMAKE) $(WEB_DIST).zip
	@echo "web-dist: $(WEB_DIST)/ and $(WEB_DIST).zip (open index.html from disk; README.md for teachers)"

test-wasm: web-deps
	@$(SUBMAKE) $(WEB_DIR)/tests.js
	@excl=""; for s in $(WASM_TEST_SKIPS); do pat=$${s%%|*}; why=$${s#*|}; \
	  echo "test-wasm: skipped $$pat: $$why"; excl="$$excl$${excl:+,}$$pat"; done; \
	node $(WEB_DIR)/tests.js -tce="$$excl"

test-web: web-dist
	bash ports/web/tests/test_web.sh $(WEB_DIR) $(WEB_DIST).zip

bench-web: web
	bash ports/web/tests/bench_web.sh $(WEB_DIR)

# Every panel at 1280x720 in Chromium and one in Firefox ESR, to look at (build/web/screenshots/).
web-screenshots: web
	bash ports/web/tests/screenshots.sh $(WEB_DIR) $(WEB_DIR)/screenshots
