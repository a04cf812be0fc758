# shitsukan - the microcontroller port's rules (ports/cortex-m and ports/riscv, see
# ports/cortex-m/README.md), included by the Makefile: make test-mcu | bench-mcu |
# footprint-mcu. Uses the Makefile's SMALL_CPPS, FLAGS_STAMP, LIBRARY, SUBMAKE and
# ensure_packages.

# Four cores: m4 (Cortex-M4F, QEMU mps2-an386), m7 (Cortex-M7, mps2-an500), m0 (Cortex-M0, no
# FPU: soft-float, micro:bit, 16 KB of RAM), rv32 (RV32IMAC, no FPU: soft-float, QEMU virt).
MCU_NEWLIB := /usr/lib/arm-none-eabi/newlib/thumb
MCU_PICOLIBC := /usr/lib/picolibc/riscv64-unknown-elf
MCU_REQUIRED := /usr/bin/arm-none-eabi-g++:gcc-arm-none-eabi \
                $(MCU_NEWLIB)/v7e-m+fp/hard/libc_nano.a:libnewlib-arm-none-eabi \
                $(MCU_NEWLIB)/v6-m/nofp/libc_nano.a:libnewlib-arm-none-eabi \
                $(MCU_NEWLIB)/v7e-m+fp/hard/libstdc++.a:libstdc++-arm-none-eabi-newlib \
                /usr/bin/qemu-system-arm:qemu-system-arm /usr/bin/clang++:clang \
                /usr/bin/riscv64-unknown-elf-g++:gcc-riscv64-unknown-elf \
                $(MCU_PICOLIBC)/lib/rv32imac/ilp32/libc.a:picolibc-riscv64-unknown-elf \
                /usr/bin/qemu-system-riscv32:qemu-system-misc

mcu-deps: deps
	$(call ensure_packages,$(MCU_REQUIRED))

# ---- microcontrollers: ports/cortex-m, ports/riscv (see ports/cortex-m/README.md) ----
# The small-device files (and render/solid_mesh.cpp, the figures' solid-texture shader) are
# compiled for each core with gcc -Os, a small C library (newlib-nano on Arm, picolibc on
# RISC-V), no exceptions, no RTTI; ports/cortex-m/test_mcu.sh runs the six transcripts
# (host gcc, host clang, M0, M4F, M7, RV32) and compares them.
MCU_DIR    := $(BUILD)/mcu
MCU_CORES  := m0 m4 m7 rv32
MCU_COMMON_SRCS := $(SMALL_CPPS) lib/shitsukan/render/solid_mesh.cpp \
                   ports/cortex-m/transcript.cpp ports/cortex-m/device_main.cpp \
                   ports/cortex-m/assert_handler.cpp
MCU_FLAGS  := -std=c++17 -Os -Wall -Wextra $(if $(CI),-Werror) -ffp-contract=off -fno-math-errno -fno-exceptions \
              -fno-rtti -fno-threadsafe-statics -fno-use-cxa-atexit -ffunction-sections \
              -fdata-sections -DSHITSUKAN_SMALL_DEVICE -Ilib -Iports/cortex-m
MCU_ARM_LD := --specs=nano.specs --specs=nosys.specs -nostartfiles -Wl,--gc-sections
MCU_ARM_PORT := ports/cortex-m/semihosting.cpp ports/cortex-m/startup.cpp
# RISC-V: Debian ships no libstdc++ for riscv64-unknown-elf; the library needs only the
# header-only parts (<cstdint>, <cmath>, <limits>, ...), taken from the Arm newlib build of
# the same GCC (12) over picolibc's C headers. No libstdc++ code is linked.
MCU_RV_CXXINC := /usr/include/newlib/c++/12.2.1

MCU_CXX_m4  := arm-none-eabi-g++
MCU_LINK_m4 := arm-none-eabi-g++
MCU_CPU_m4  := -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard
MCU_LD_m4   := $(MCU_ARM_LD) -T ports/cortex-m/mps2.ld
MCU_LDS_m4  := ports/cortex-m/mps2.ld ports/cortex-m/sections.ld
MCU_PORT_m4 := $(MCU_ARM_PORT)
MCU_SIZE_m4 := arm-none-eabi-size
MCU_BENCH_m4 := -DBENCH_CORE='"M4F"'
MCU_CXX_m7  := arm-none-eabi-g++
MCU_LINK_m7 := arm-none-eabi-g++
MCU_CPU_m7  := -mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard
MCU_LD_m7   := $(MCU_LD_m4)
MCU_LDS_m7  := $(MCU_LDS_m4)
MCU_PORT_m7 := $(MCU_ARM_PORT)
MCU_SIZE_m7 := arm-none-eabi-size
MCU_BENCH_m7 := -DBENCH_CORE='"M7"'
# The M0's 16 KB of RAM: no Type I table (D(P) from Type III without its row cache) and
# 512-pixel bands (one row of fig. 10a's 512, three of the lit box's 160); a 4 KB stack
# (-fstack-usage: the rasterizer's draw frame alone is 2,128 bytes on Armv6-M; a 2 KB stack
# overflowed into .bss and faulted).
MCU_CXX_m0  := arm-none-eabi-g++
MCU_LINK_m0 := arm-none-eabi-g++
MCU_CPU_m0  := -mcpu=cortex-m0 -mthumb -mfloat-abi=soft -DSHITSUKAN_TYPE3_ROW_CACHE=0 \
               -DTRANSCRIPT_NO_TABLE -DTRANSCRIPT_BAND_PIXELS=512
MCU_LD_m0   := $(MCU_ARM_LD) -T ports/cortex-m/microbit.ld
MCU_STACK_m0 := -Wl,--defsym=STACK_SIZE=4096
MCU_LDS_m0  := ports/cortex-m/microbit.ld ports/cortex-m/sections.ld
# The M0's soft-float run-time pieces in place of libgcc's larger ones (same results; see each
# file): subtraction, comparisons, double add/multiply/divide, signed division. Not the float
# add/multiply/divide of soft_single.hpp: 1.4 KB less flash, but 25 % more instructions per
# lattice node and marble pixel on the M0 (make bench-mcu), and the lattice and marble
# firmwares meet their goals without them.
MCU_SOFT_m0 := ports/cortex-m/soft_float_sub.cpp ports/cortex-m/soft_float_compare.cpp \
               ports/cortex-m/soft_double.cpp ports/cortex-m/signed_divide.cpp
MCU_PORT_m0 := $(MCU_ARM_PORT) $(MCU_SOFT_m0)
MCU_SIZE_m0 := arm-none-eabi-size
MCU_BENCH_m0 := -DBENCH_CORE='"M0"' -DBENCH_SMALL_RAM -DBOARD_MICROBIT
MCU_CXX_rv32  := riscv64-unknown-elf-g++
MCU_LINK_rv32 := riscv64-unknown-elf-gcc
MCU_CPU_rv32  := -march=rv32imac -mabi=ilp32 -mcmodel=medany --specs=picolibc.specs -nostdinc++ \
                 -isystem $(MCU_RV_CXXINC) -isystem $(MCU_RV_CXXINC)/arm-none-eabi/thumb/v6-m/nofp
MCU_LD_rv32   := -nostartfiles -Wl,--gc-sections -T ports/riscv/virt.ld
MCU_LDS_rv32  := ports/riscv/virt.ld
# RV32: the same, and the float add/multiply/divide (soft_single.hpp: 1.3 KB less flash, which
# the marble firmware's goal needs; 5-12 % more instructions per lattice node and marble or wood
# pixel, 13 % fewer per rasterized pixel: make bench-mcu).
MCU_SOFT_rv32 := ports/cortex-m/soft_float_sub.cpp ports/riscv/soft_float_compare.cpp \
                 ports/cortex-m/soft_double.cpp ports/riscv/soft_single.cpp
MCU_PORT_rv32 := ports/cortex-m/semihosting.cpp ports/riscv/startup.cpp $(MCU_SOFT_rv32)
MCU_SIZE_rv32 := riscv64-unknown-elf-size
MCU_BENCH_rv32 := -DBENCH_CORE='"RV32"'

MCU_TRANSCRIPTS := $(foreach c,$(MCU_CORES),$(MCU_DIR)/$(c)/transcript.elf)
# tests/mcu/soft_double_check.cpp: ports/cortex-m/soft_double.hpp against the device's own
# libgcc (linked without the port's replacements), on the two soft-float cores.
MCU_SOFT_CHECKS := $(foreach c,m0 rv32,$(MCU_DIR)/$(c)/soft_double_check.elf)
test-mcu: mcu-deps
	@$(SUBMAKE) $(MCU_TRANSCRIPTS) $(MCU_SOFT_CHECKS) $(MCU_DIR)/host_transcript \
	  $(MCU_DIR)/host_clang_O0 $(MCU_DIR)/png_fnv $(BUILD)/paper_figures
	bash ports/cortex-m/qemu_run.sh m0 $(MCU_DIR)/m0/soft_double_check.elf
	bash ports/cortex-m/qemu_run.sh rv32 $(MCU_DIR)/rv32/soft_double_check.elf
	bash ports/cortex-m/test_mcu.sh $(MCU_DIR) $(BUILD)/paper_figures

# Instructions per lattice node / marble pixel / rasterized pixel / triangle on each core
# (QEMU -icount: one instruction per ns of virtual time; ports/cortex-m/icount.hpp).
MCU_BENCH_SRCS = $(filter-out ports/cortex-m/transcript.cpp ports/cortex-m/device_main.cpp,\
                   $(MCU_COMMON_SRCS)) ports/cortex-m/bench_main.cpp
bench-mcu: mcu-deps
	@$(SUBMAKE) $(foreach c,$(MCU_CORES),$(MCU_DIR)/$(c)/bench.elf)
	@bash ports/cortex-m/bench_mcu.sh $(MCU_DIR)

# The firmwares of the footprint goals (ports/cortex-m/footprint_main.cpp): lattice only and
# the marble cube, for the M4F, the M0 and the RV32, built, run and measured by
# ports/cortex-m/footprint.sh (flash = text + data, RAM = data + bss + the stack's
# high-water mark).
# -flto: the firmware is compiled and linked in one step, so link-time optimisation sees the
# whole program (inlines across files, drops what is unreachable): 0.6-2.6 KB less flash per
# firmware; the digests they print are those of the transcript's builds (footprint.sh checks
# that the cores agree). Not for the transcript: its map file names the objects per module.
# -fno-inline-small-functions: -Os still inlines small functions at each call, and with the
# whole program in view that copied the rasterizer's helpers into every caller (the binned
# rasterizer's helpers put the M0 and RV32 marble firmwares 0.5 KB over 32 KB); without it the
# marble firmwares are 2.0 KB (M0) and 3.5 KB (RV32) smaller. Same digests; the speed of these
# firmwares is not measured (make bench-mcu builds its own, without either flag).
# -DSHITSUKAN_STATUS_NO_ARGUMENTS (core/status.hpp): the firmwares check every Status but
# print none, so a Status keeps its code and format without the arguments, and the argument
# walk is not linked; the lattice_messages variant is built without it, so its footprint line
# is what a porter who prints messages pays. Every other build (host, transcript, bench) keeps
# the arguments.
# RV32: -msave-restore (prologues and epilogues through shared libgcc routines): 0.9 KB less.
MCU_FP_FLAGS := -flto -fno-inline-small-functions
# The firmwares, and the two lattice variants that measure section 7's choices (footprint_main).
MCU_FP_VARIANTS := lattice marble lattice_runtime_beta lattice_messages
MCU_FP_FLAGS_rv32 := -msave-restore
MCU_FP_SRCS = $(filter-out ports/cortex-m/transcript.cpp ports/cortex-m/device_main.cpp \
                 lib/shitsukan/render/solid_mesh.cpp,$(MCU_COMMON_SRCS)) ports/cortex-m/footprint_main.cpp
footprint-mcu: mcu-deps
	@$(SUBMAKE) $(foreach c,m4 m0 rv32,$(foreach v,$(MCU_FP_VARIANTS),$(MCU_DIR)/footprint/$(c)-$(v).elf))
	@bash ports/cortex-m/footprint.sh firmwares $(MCU_DIR)/footprint

# The same program built by clang at -O0 (library sources included): same bits as gcc -O2.
MCU_HOST_SRCS := $(filter-out ports/cortex-m/device_main.cpp ports/cortex-m/assert_handler.cpp,\
                   $(MCU_COMMON_SRCS)) ports/cortex-m/host_main.cpp
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

# $(1): the core. Objects per core; the transcript, bench and footprint firmwares. (Every
# MCU_*_$(1) is set above: $(call) expands them before the eval.)
define mcu_core
$(MCU_DIR)/$(1)/%.o: %.cpp $(FLAGS_STAMP)
	@mkdir -p $$(@D)
	$(MCU_CXX_$(1)) $(MCU_CPU_$(1)) $(MCU_FLAGS) $$(MCU_EXTRA) -MMD -MP -c $$< -o $$@
$(MCU_DIR)/$(1)/ports/cortex-m/bench_main.o: MCU_EXTRA := $(MCU_BENCH_$(1))

$(MCU_DIR)/$(1)/bench.elf: $(patsubst %.cpp,$(MCU_DIR)/$(1)/%.o,$(MCU_BENCH_SRCS) $(MCU_PORT_$(1))) $(MCU_LDS_$(1))
	$(MCU_LINK_$(1)) $(MCU_CPU_$(1)) $(MCU_LD_$(1)) $(MCU_STACK_$(1)) -o $$@ \
	  $(patsubst %.cpp,$(MCU_DIR)/$(1)/%.o,$(MCU_BENCH_SRCS) $(MCU_PORT_$(1)))

$(MCU_DIR)/$(1)/soft_double_check.elf: $(patsubst %.cpp,$(MCU_DIR)/$(1)/%.o,tests/mcu/soft_double_check.cpp $(filter-out $(MCU_SOFT_$(1)),$(MCU_PORT_$(1)))) $(MCU_LDS_$(1))
	$(MCU_LINK_$(1)) $(MCU_CPU_$(1)) $(MCU_LD_$(1)) $(MCU_STACK_$(1)) -o $$@ \
	  $(patsubst %.cpp,$(MCU_DIR)/$(1)/%.o,tests/mcu/soft_double_check.cpp $(filter-out $(MCU_SOFT_$(1)),$(MCU_PORT_$(1))))

$(MCU_DIR)/$(1)/transcript.elf: $(patsubst %.cpp,$(MCU_DIR)/$(1)/%.o,$(MCU_COMMON_SRCS) $(MCU_PORT_$(1))) $(MCU_LDS_$(1))
	$(MCU_LINK_$(1)) $(MCU_CPU_$(1)) $(MCU_LD_$(1)) $(MCU_STACK_$(1)) -Wl,-Map=$$(@:.elf=.map) -o $$@ \
	  $(patsubst %.cpp,$(MCU_DIR)/$(1)/%.o,$(MCU_COMMON_SRCS) $(MCU_PORT_$(1)))
	@$(MCU_SIZE_$(1)) $$@

# Footprint firmwares: the Type III row cache off, 8 KB of stack reserved (measured, not
# counted: RAM counts the high-water mark), link-time optimisation (MCU_FP_FLAGS).
$(MCU_DIR)/footprint/$(1)-%.elf: $(MCU_FP_SRCS) $(MCU_PORT_$(1)) $(MCU_LDS_$(1)) $(FLAGS_STAMP) ports/cortex-m/mcu.mk
	@mkdir -p $$(@D)
	$(MCU_LINK_$(1)) $(MCU_CPU_$(1)) $(MCU_FLAGS) $(MCU_FP_FLAGS) $(MCU_FP_FLAGS_$(1)) \
	  $$(if $$(filter lattice_messages,$$*),,-DSHITSUKAN_STATUS_NO_ARGUMENTS) -DSHITSUKAN_TYPE3_ROW_CACHE=0 \
	  -DFOOTPRINT_$$(shell echo $$* | tr a-z A-Z) $(MCU_LD_$(1)) \
	  -Wl,--defsym=STACK_SIZE=$(if $(filter m0,$(1)),4096,8192) -Wl,-Map=$$(@:.elf=.map) -o $$@ \
	  $(MCU_FP_SRCS) $(MCU_PORT_$(1))
endef
$(foreach c,$(MCU_CORES),$(eval $(call mcu_core,$(c))))
