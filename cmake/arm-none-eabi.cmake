# A CMake toolchain file for bare-metal Cortex-M with Debian's
# gcc-arm-none-eabi and newlib-nano:
#   cmake -S app -B build-arm -DCMAKE_TOOLCHAIN_FILE=path/to/fxrt/cmake/arm-none-eabi.cmake \
#         [-DFXRT_CPU_FLAGS="-mcpu=cortex-m0 -mthumb"]
# Programs link with newlib-nano, without its start files (the program
# brings its own start-up and linker script, as fxrt's firmware does) and
# with unused sections dropped.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
# The compiler cannot link a program without a linker script: test it on
# a static library.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(FXRT_CPU_FLAGS "-mcpu=cortex-m3 -mthumb -mfloat-abi=soft" CACHE STRING
    "CPU flags (micro:bit: -mcpu=cortex-m0 -mthumb; MPS2-AN386: -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16)")
set(CMAKE_C_FLAGS_INIT "${FXRT_CPU_FLAGS}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${FXRT_CPU_FLAGS} -nostartfiles --specs=nano.specs --specs=nosys.specs -Wl,--gc-sections")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
