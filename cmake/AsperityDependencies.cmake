# Every dependency is found through find_package or pkg-config from Debian's packages.
find_package(Threads REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(CLI11 REQUIRED)

find_package(meshoptimizer REQUIRED)
find_package(tinyobjloader REQUIRED)
# glTF, FBX, COLLADA and 3DS meshes with their materials (Open Asset Import Library).
find_package(assimp 5 REQUIRED)
# oneTBB runs the samples of `asperity sweep` on a pool of threads.
find_package(TBB REQUIRED)
# zlib's CRC-32 checks every PNG chunk before stb decodes it.
find_package(ZLIB REQUIRED)
find_package(PkgConfig REQUIRED)
# Bullet (single precision, as Debian builds it) for broadphase and convex contacts.
pkg_check_modules(BULLET REQUIRED IMPORTED_TARGET bullet)
# cairo draws the command-line tool's plots (one routine, SVG and PNG surfaces).
pkg_check_modules(CAIRO REQUIRED IMPORTED_TARGET cairo)

# stb ships headers and a pkg-config file; PNG encode/decode is compiled once in the core.
find_path(STB_INCLUDE_DIR stb_image.h PATH_SUFFIXES stb REQUIRED)

if(ASPERITY_WITH_GL)
  pkg_check_modules(EPOXY REQUIRED IMPORTED_TARGET epoxy)
  pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)
  pkg_check_modules(GLFW REQUIRED IMPORTED_TARGET glfw3)
  pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
endif()

if(ASPERITY_BUILD_TESTS)
  find_package(GTest REQUIRED)
  include(GoogleTest)
endif()
if(ASPERITY_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()

# The Python module: Debian's interpreter (/usr/bin/python3), never another python3 on PATH, so
# that `cmake --install` puts the module where Debian's python3 and its NumPy find it.
if(ASPERITY_WITH_PYTHON)
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3)
  endif()
  set(PYBIND11_FINDPYTHON ON)
  find_package(Python 3.9 REQUIRED COMPONENTS Interpreter Development.Module NumPy)
  find_package(pybind11 2.6 CONFIG REQUIRED)
endif()

# Engine adapters (docs/engines.md), each built when its Debian package is found: MuJoCo 2.2
# (libmujoco-dev) and ODE (libode-dev).
if(ASPERITY_WITH_MUJOCO)
  find_package(mujoco CONFIG QUIET)
  if(TARGET mujoco::mujoco)
    # Debian's 2.2.2 package names /usr/include/libqhull_r/, which it does not install; CMake
    # refuses imported targets with missing include folders, so keep only those that exist.
    get_target_property(mujoco_includes mujoco::mujoco INTERFACE_INCLUDE_DIRECTORIES)
    set(mujoco_existing)
    foreach(folder ${mujoco_includes})
      if(EXISTS "${folder}")
        list(APPEND mujoco_existing "${folder}")
      endif()
    endforeach()
    set_target_properties(mujoco::mujoco PROPERTIES INTERFACE_INCLUDE_DIRECTORIES
                                                    "${mujoco_existing}")
  endif()
endif()
if(ASPERITY_WITH_ODE)
  pkg_check_modules(ODE QUIET IMPORTED_TARGET ode)
endif()

# Float height maps in OpenEXR (docs/contact-area.md), read when Debian's libopenexr-dev is
# found; scripts/install-deps.sh installs it, so CI has it, and ASPERITY_REQUIRE_OPENEXR makes
# its absence an error there.
if(ASPERITY_WITH_OPENEXR)
  pkg_check_modules(OPENEXR QUIET OpenEXR)
  if(ASPERITY_REQUIRE_OPENEXR AND NOT OPENEXR_FOUND)
    message(FATAL_ERROR "ASPERITY_REQUIRE_OPENEXR: libopenexr-dev not found")
  endif()
endif()
