# shitsukan - the microcontroller port's rules (ports/cortex-m, see its README.md), included by
# the Makefile: make test-mcu | bench-mcu | footprint-mcu. Uses the Makefile's SMALL_CPPS,
# FLAGS_STAMP, LIBRARY, SUBMAKE and ensure_packages.

MCU_NEWLIB := /usr/lib/arm-none-eabi/newlib/thumb/v7e-m+fp/hard
MCU_REQUIRED := /usr/bin/arm-none-eabi-g++:gcc-arm-none-eabi \
                $(MCU_NEWLIB)/libc_nano.a:libnewlib-arm-none-eabi \
                $(MCU_NEWLIB)/libstdc++.a:libstdc++-arm-none-eabi-newlib \
                /usr/bin/qemu-system-arm:qemu-system-arm /usr/bin/clang++:clang

mcu-deps: deps
	$(call ensure_packages,$(MCU_REQUIRED))

# ---- microcontrollers: ports/cortex-m (see its README.md) ----
# The small-device files (and render/solid_mesh.cpp, the figures' solid-texture shader) are
# compiled for each core with arm-none-eabi-g++ -Os, newlib-nano, no exceptions, no RTTI;
# ports/cortex-m/test_mcu.sh runs the three transcripts and compares them.
MCU_CXX    := arm-none-eabi-g++
MCU_DIR    := $(BUILD)/mcu
MCU_SRCS   := $(SMALL_CPPS) \
              lib/shitsukan/render/solid_mesh.cpp ports/cortex-m/transcript.cpp \
              ports/cortex-m/semihosting.cpp ports/cortex-m/startup.cpp \
              ports/cortex-m/device_main.cpp ports/cortex-m/assert_handler.cpp
MCU_FLAGS  := -std=c++17 -Os -Wall -Wextra $(if $(CI),-Werror) -ffp-contract=off -fno-exceptions \
              -fno-rtti -fno-threadsafe-statics -fno-use-cxa-atexit -ffunction-sections \
              -fdata-sections -DSHITSUKAN_SMALL_DEVICE -Ilib -Iports/cortex-m
MCU_CPU_m4 := -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard
MCU_CPU_m7 := -mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard
MCU_LDFLAGS := --specs=nano.specs --specs=nosys.specs -nostartfiles -Wl,--gc-sections \
               -T ports/cortex-m/mps2.ld

test-mcu: mcu-deps
	@$(SUBMAKE) $(MCU_DIR)/m4/transcript.elf $(MCU_DIR)/m7/transcript.elf \
	  $(MCU_DIR)/host_transcript $(MCU_DIR)/host_clang_O0 $(MCU_DIR)/png_fnv $(BUILD)/paper_figures
	bash ports/cortex-m/test_mcu.sh $(MCU_DIR) $(BUILD)/paper_figures

# Instructions per lattice node / marble pixel / rasterized pixel on the Cortex-M4F (QEMU
# -icount: one instruction per ns of virtual time, read from the MPS2 timer).
MCU_BENCH_SRCS := $(filter-out ports/cortex-m/transcript.cpp ports/cortex-m/device_main.cpp,$(MCU_SRCS)) \
                  ports/cortex-m/bench_main.cpp
bench-mcu: mcu-deps
	@$(SUBMAKE) $(MCU_DIR)/m4/bench.elf
	@qemu-system-arm -M mps2-an386 -icount shift=0 -display none -monitor none -serial none \
	  -chardev stdio,id=semi -semihosting-config enable=on,target=native,chardev=semi \
	  -kernel $(MCU_DIR)/m4/bench.elf

# The firmwares of the README's footprint table (ports/cortex-m/footprint_main.cpp), M4F -Os
# newlib-nano, Type III row cache off: built, run, measured (flash = text + data, RAM = data +
# bss + the main stack's high-water mark).
MCU_FP_SRCS := $(filter-out ports/cortex-m/transcript.cpp ports/cortex-m/device_main.cpp \
                 lib/shitsukan/render/solid_mesh.cpp,$(MCU_SRCS)) ports/cortex-m/footprint_main.cpp
MCU_FP_FLAGS := $(MCU_CPU_m4) $(MCU_FLAGS) -DSHITSUKAN_TYPE3_ROW_CACHE=0
MCU_FP_STACK := 8192
footprint-mcu: mcu-deps
	@mkdir -p $(MCU_DIR)/footprint
	@for v in LATTICE MARBLE; do \
	  $(MCU_CXX) $(MCU_FP_FLAGS) -DFOOTPRINT_$$v $(MCU_LDFLAGS) -Wl,--defsym=STACK_SIZE=$(MCU_FP_STACK) \
	    -o $(MCU_DIR)/footprint/$$v.elf $(MCU_FP_SRCS) || exit 1; \
	  out=$$(qemu-system-arm -M mps2-an386 -display none -monitor none -serial none \
	    -chardev stdio,id=semi -semihosting-config enable=on,target=native,chardev=semi \
	    -kernel $(MCU_DIR)/footprint/$$v.elf) || { echo "footprint-mcu: $$v failed"; exit 1; }; \
	  echo "$$out"; stack=$$(echo "$$out" | sed -n 's/.*main stack used \([0-9]*\) bytes/\1/p'); \
	  arm-none-eabi-size $(MCU_DIR)/footprint/$$v.elf | awk -v v=$$v -v s=$$stack -v r=$(MCU_FP_STACK) 'NR == 2 { \
	    printf "footprint: %s firmware (M4F, -Os, newlib-nano): flash %d bytes, RAM %d bytes (data %d + bss %d + stack used %d)\n", \
	    v, $$1 + $$2, $$2 + $$3 - r + s, $$2, $$3 - r, s }'; done

# The same program built by clang at -O0 (library sources included): same bits as gcc -O2.
MCU_HOST_SRCS := $(filter-out ports/cortex-m/semihosting.cpp ports/cortex-m/startup.cpp \
                   ports/cortex-m/device_main.cpp ports/cortex-m/assert_handler.cpp,$(MCU_SRCS)) \
                 ports/cortex-m/host_main.cpp
$(MCU_DIR)/host_clang_O0: $(MCU_HOST_SRCS) $(FLAGS_STAMP)
	@mkdir -p $(@D)
	clang++ -std=c++17 -O0 -ffp-contract=off -Ilib -Iports/cortex-m -o $@ $(MCU_HOST_SRCS)

$(MCU_DIR)/host_transcript: ports/cortex-m/host_main.cpp ports/cortex-m/transcript.cpp \
                            ports/cortex-m/transcript.hpp $(LIBRARY)
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) $(CXXFLAGS) -Iports/cortex-m -o $@ ports/cortex-m/host_main.cpp \
	  ports/cortex-m/transcript.cpp $(LIBRARY)

$(MCU_DIR)/png_fnv: tests/mcu/png_fnv.cpp
	@mkdir -p $(@D)
	$(CXX) -std=c++17 -O2 -w -o $@ $<

define mcu_core
$(MCU_DIR)/$(1)/%.o: %.cpp $(FLAGS_STAMP)
	@mkdir -p $$(@D)
	$(MCU_CXX) $(MCU_CPU_$(1)) $(MCU_FLAGS) -MMD -MP -c $$< -o $$@

$(MCU_DIR)/$(1)/bench.elf: $(MCU_BENCH_SRCS:%.cpp=$(MCU_DIR)/$(1)/%.o) ports/cortex-m/mps2.ld
	$(MCU_CXX) $(MCU_CPU_$(1)) $(MCU_LDFLAGS) -o $$@ $(MCU_BENCH_SRCS:%.cpp=$(MCU_DIR)/$(1)/%.o)

$(MCU_DIR)/$(1)/transcript.elf: $(MCU_SRCS:%.cpp=$(MCU_DIR)/$(1)/%.o) ports/cortex-m/mps2.ld
	$(MCU_CXX) $(MCU_CPU_$(1)) $(MCU_LDFLAGS) -Wl,-Map=$$(@:.elf=.map) -o $$@ \
	  $(MCU_SRCS:%.cpp=$(MCU_DIR)/$(1)/%.o)
	@arm-none-eabi-size $$@
endef
$(eval $(call mcu_core,m4))
$(eval $(call mcu_core,m7))
