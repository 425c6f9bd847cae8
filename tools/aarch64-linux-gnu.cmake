# Cross-compiling for AArch64 (a recent Mac's Linux container, a Raspberry Pi) on a Debian x86-64
# machine: Debian's g++-aarch64-linux-gnu, the arm64 builds of the libraries (multiarch:
# `dpkg --add-architecture arm64`, then PACKAGE:arm64; ./lab cross installs them), and the
# programs run under qemu-user. The header-only packages are the host's (/usr/include, /usr/share):
# they are the same on every architecture.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
# Libraries, CMake packages and pkg-config files from the arm64 directories, never the host's.
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)
set(ENV{PKG_CONFIG_LIBDIR} /usr/lib/aarch64-linux-gnu/pkgconfig:/usr/share/pkgconfig)
# ctest runs each test program through qemu; the arm64 libc's loader (libc6:arm64) is where the
# programs look for it, so no -L prefix is needed.
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64)
