# Locate MuJoCo and define the imported target mujoco::mujoco.
#
# Order of preference:
#   1. A regular install found by find_package(mujoco) (release tarball or source build).
#   2. The PyPI wheel `mujoco` pinned in requirements.txt, found through SSC_PYTHON
#      (default: <repo>/.venv/bin/python). The wheel ships libmujoco.so.X.Y.Z (no unversioned
#      link) and headers under mujoco/include; we link the absolute path and set an rpath.
#
# Either way SSC_MUJOCO_PINNED holds the version pinned in requirements.txt, and the headers
# must match it (a mismatch is a configure error, not a runtime surprise).

# Copies the files of `src` into `dst`, writing only those whose content differs (their
# timestamps stay otherwise): a stable path for files from a folder that moves between builds.
function(ssc_mirror_dir src dst)
  file(GLOB_RECURSE _files RELATIVE "${src}" "${src}/*")
  foreach(f ${_files})
    if(NOT f MATCHES "__pycache__")
      configure_file("${src}/${f}" "${dst}/${f}" COPYONLY)
    endif()
  endforeach()
endfunction()

file(STRINGS "${PROJECT_SOURCE_DIR}/requirements.txt" _ssc_pin REGEX "^mujoco==")
string(REGEX REPLACE "^mujoco==([0-9.]+).*" "\\1" SSC_MUJOCO_PINNED "${_ssc_pin}")
if(NOT SSC_MUJOCO_PINNED)
  message(FATAL_ERROR "requirements.txt: no 'mujoco==X.Y.Z' line; the MuJoCo pin lives there")
endif()

option(SSC_USE_SYSTEM_MUJOCO "Prefer a regular MuJoCo install found by find_package(mujoco)" ON)
set(SSC_PYTHON "${PROJECT_SOURCE_DIR}/.venv/bin/python" CACHE FILEPATH
    "Python interpreter whose site-packages hold the pinned mujoco wheel")

set(_ssc_found_mujoco FALSE)
if(SSC_USE_SYSTEM_MUJOCO)
  find_package(mujoco CONFIG QUIET)
  if(TARGET mujoco::mujoco)
    set(_ssc_found_mujoco TRUE)
    get_target_property(SSC_MUJOCO_INCLUDE_DIR mujoco::mujoco INTERFACE_INCLUDE_DIRECTORIES)
    message(STATUS "MuJoCo: regular install (find_package) at ${mujoco_DIR}")
  endif()
endif()

if(NOT _ssc_found_mujoco)
  if(NOT EXISTS "${SSC_PYTHON}")
    message(FATAL_ERROR
      "MuJoCo not found. Either install MuJoCo so that find_package(mujoco) works, or run "
      "tools/setup.sh, which creates .venv/ with mujoco==${SSC_MUJOCO_PINNED} from PyPI "
      "(or pass -DSSC_PYTHON=/path/to/python with that wheel installed).")
  endif()
  execute_process(
    COMMAND "${SSC_PYTHON}" -c
            "import mujoco, os; print(mujoco.__version__); print(os.path.dirname(mujoco.__file__))"
    OUTPUT_VARIABLE _ssc_py_out RESULT_VARIABLE _ssc_py_rc ERROR_VARIABLE _ssc_py_err
    OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT _ssc_py_rc EQUAL 0)
    message(FATAL_ERROR "${SSC_PYTHON} cannot import mujoco: ${_ssc_py_err}\n"
                        "Run tools/setup.sh to create the venv with the pinned wheel.")
  endif()
  string(REPLACE "\n" ";" _ssc_py_lines "${_ssc_py_out}")
  list(GET _ssc_py_lines 0 _ssc_wheel_version)
  list(GET _ssc_py_lines 1 SSC_MUJOCO_WHEEL_DIR)
  if(NOT _ssc_wheel_version STREQUAL SSC_MUJOCO_PINNED)
    message(FATAL_ERROR "The venv has mujoco ${_ssc_wheel_version}, requirements.txt pins "
                        "${SSC_MUJOCO_PINNED}. Run tools/setup.sh to reinstall.")
  endif()
  set(SSC_MUJOCO_LIBRARY "${SSC_MUJOCO_WHEEL_DIR}/libmujoco.so.${_ssc_wheel_version}")
  if(NOT EXISTS "${SSC_MUJOCO_LIBRARY}")
    message(FATAL_ERROR "Wheel layout changed: ${SSC_MUJOCO_LIBRARY} does not exist")
  endif()
  set(SSC_MUJOCO_INCLUDE_DIR "${SSC_MUJOCO_WHEEL_DIR}/include")
  if(SKBUILD)
    # pip's build isolation installs the wheel into a new temporary folder for every build: with
    # the headers included from there, each `pip install .` would change every compile command
    # and rebuild everything. A copy in the build tree (rewritten only where a header changed)
    # keeps unchanged objects up to date.
    ssc_mirror_dir("${SSC_MUJOCO_INCLUDE_DIR}" "${PROJECT_BINARY_DIR}/_deps/mujoco_include")
    set(SSC_MUJOCO_INCLUDE_DIR "${PROJECT_BINARY_DIR}/_deps/mujoco_include")
  endif()
  set(SSC_MUJOCO_PLUGIN_DIR "${SSC_MUJOCO_WHEEL_DIR}/plugin")
  add_library(mujoco::mujoco SHARED IMPORTED GLOBAL)
  set_target_properties(mujoco::mujoco PROPERTIES
    IMPORTED_LOCATION "${SSC_MUJOCO_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${SSC_MUJOCO_INCLUDE_DIR}")
  # The wheel's library has its full version as SONAME; the build rpath lets binaries in the
  # build tree find it. `cmake --install` copies it into lib/ (cmake/Install.cmake): installed
  # binaries find it there through $ORIGIN, never in the builder's venv.
  list(APPEND CMAKE_BUILD_RPATH "${SSC_MUJOCO_WHEEL_DIR}")
  message(STATUS "MuJoCo: PyPI wheel ${_ssc_wheel_version} at ${SSC_MUJOCO_WHEEL_DIR}")
endif()

# Headers must be the pinned version (mjVERSION_HEADER is e.g. 4000000 for 4.0.0).
find_file(_ssc_mujoco_h mujoco/mujoco.h PATHS ${SSC_MUJOCO_INCLUDE_DIR} NO_DEFAULT_PATH)
if(_ssc_mujoco_h)
  file(STRINGS "${_ssc_mujoco_h}" _ssc_vh REGEX "#define mjVERSION_HEADER")
  string(REGEX REPLACE ".*mjVERSION_HEADER[ \t]+([0-9]+).*" "\\1" SSC_MUJOCO_HEADER_VERSION "${_ssc_vh}")
  string(REPLACE "." ";" _ssc_pin_parts "${SSC_MUJOCO_PINNED}")
  list(GET _ssc_pin_parts 0 _maj)
  list(GET _ssc_pin_parts 1 _min)
  list(GET _ssc_pin_parts 2 _pat)
  math(EXPR _ssc_expect "${_maj} * 1000000 + ${_min} * 1000 + ${_pat}")
  if(NOT SSC_MUJOCO_HEADER_VERSION EQUAL _ssc_expect)
    message(WARNING "MuJoCo headers are version ${SSC_MUJOCO_HEADER_VERSION}, the project is "
                    "pinned to ${SSC_MUJOCO_PINNED} (${_ssc_expect}); results may differ.")
  endif()
  if(SSC_MUJOCO_HEADER_VERSION LESS 3000000)
    message(FATAL_ERROR "MuJoCo ${SSC_MUJOCO_HEADER_VERSION} is too old: the engine plugin API "
                        "needs 3.x or newer (Debian's libmujoco-dev 2.2.2 will not do).")
  endif()
endif()
