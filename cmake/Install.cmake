# `cmake --install`: the libraries with their headers, the MuJoCo plugin, `ssc`, the models,
# scenes and plot scripts, and a package config so that a downstream project does
#   find_package(ssc CONFIG REQUIRED)   target_link_libraries(app PRIVATE ssc::ssc)
# Layout under the prefix:
#   bin/ssc   lib/libssc_*.a   lib/libssc_plugin.so   include/ssc/<folder>/*.h
#   share/ssc/{models,scenes,tools}   lib/cmake/ssc/ssc{Config,ConfigVersion,Targets}.cmake
# Installed binaries find share/ssc next to them (ResourceDir() in the MuJoCo adapters).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SSC_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/ssc")
set(SSC_INSTALL_INCLUDEDIR "${CMAKE_INSTALL_INCLUDEDIR}/ssc")
set(SSC_INSTALL_DATADIR "${CMAKE_INSTALL_DATADIR}/ssc")

# The libraries a downstream program links: every library target of the library folders (the
# viewer stays with `ssc`: it needs GLFW), so a new library is exported without a list to edit.
set(SSC_LIBRARY_FOLDERS common plugin geometry controller trial calibration objects runtime
    studies robotlog compare)
set(SSC_EXPORTED_LIBRARIES ssc_warnings)
foreach(dir ${SSC_LIBRARY_FOLDERS})
  if(IS_DIRECTORY "${PROJECT_SOURCE_DIR}/${dir}")
    get_property(_targets DIRECTORY "${PROJECT_SOURCE_DIR}/${dir}" PROPERTY BUILDSYSTEM_TARGETS)
    foreach(t ${_targets})
      get_target_property(_type ${t} TYPE)
      if(_type MATCHES "^(STATIC|SHARED)_LIBRARY$")
        list(APPEND SSC_EXPORTED_LIBRARIES ${t})
      endif()
    endforeach()
  endif()
endforeach()
foreach(t ${SSC_EXPORTED_LIBRARIES})
  # Targets say PUBLIC "${PROJECT_SOURCE_DIR}" for the build; installed, the headers live in
  # include/ssc with the same sub-folders.
  if(NOT t STREQUAL "ssc_warnings")
    set_target_properties(${t} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES
      "$<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>;$<INSTALL_INTERFACE:${SSC_INSTALL_INCLUDEDIR}>")
  endif()
  string(REGEX REPLACE "^ssc_" "" _export_name "${t}")
  set_target_properties(${t} PROPERTIES EXPORT_NAME ${_export_name})
endforeach()
# ssc::ssc: everything above in one name.
add_library(ssc_all INTERFACE)
list(REMOVE_ITEM SSC_EXPORTED_LIBRARIES ssc_warnings)  # static libraries list it privately
target_link_libraries(ssc_all INTERFACE ${SSC_EXPORTED_LIBRARIES})
set_target_properties(ssc_all PROPERTIES EXPORT_NAME ssc)

# Installed `ssc` and the plugin find each other and MuJoCo through $ORIGIN-relative rpaths, so
# the prefix can move. Installed: the plugin beside libmujoco in lib/; in the Python wheel the
# plugin sits in ssc_twin/, libmujoco in ../mujoco.
set_target_properties(ssc PROPERTIES INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR};${CMAKE_INSTALL_RPATH}")
set_target_properties(ssc_plugin PROPERTIES INSTALL_RPATH "$ORIGIN;$ORIGIN/../mujoco;${CMAKE_INSTALL_RPATH}")

install(TARGETS ssc_all ssc_warnings ${SSC_EXPORTED_LIBRARIES} EXPORT sscTargets
        RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}"
        LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
        ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(TARGETS ssc RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
# `ssc bench` runs the benchmark binary that sits next to `ssc`.
if(TARGET ssc_bench)
  set_target_properties(ssc_bench PROPERTIES INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR};${CMAKE_INSTALL_RPATH}")
  install(TARGETS ssc_bench RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
endif()
install(EXPORT sscTargets NAMESPACE ssc:: DESTINATION "${SSC_INSTALL_CMAKEDIR}")

# Headers of every library folder, keeping the paths the sources include them by.
foreach(dir ${SSC_LIBRARY_FOLDERS})
  if(IS_DIRECTORY "${PROJECT_SOURCE_DIR}/${dir}")
    install(DIRECTORY "${PROJECT_SOURCE_DIR}/${dir}" DESTINATION "${SSC_INSTALL_INCLUDEDIR}"
            FILES_MATCHING PATTERN "*.h" PATTERN "fuzz" EXCLUDE PATTERN "tools" EXCLUDE)
  endif()
endforeach()
install(DIRECTORY "${PROJECT_SOURCE_DIR}/models" "${PROJECT_SOURCE_DIR}/scenes"
        DESTINATION "${SSC_INSTALL_DATADIR}")
# The published success map, ssc validate's default --map.
install(DIRECTORY "${PROJECT_SOURCE_DIR}/data/published" DESTINATION "${SSC_INSTALL_DATADIR}/data")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/tools/" DESTINATION "${SSC_INSTALL_DATADIR}/tools"
        FILES_MATCHING PATTERN "plot_*.py")
install(FILES "${PROJECT_SOURCE_DIR}/requirements.txt" DESTINATION "${SSC_INSTALL_DATADIR}")

# Other packages' imported targets the libraries link (privately too: a static library passes
# them on), e.g. NLopt::nlopt, nlohmann_json::nlohmann_json, MPI::MPI_CXX, Eigen3::Eigen,
# mujoco::mujoco: per library, with what the libraries it links need, so that
# find_package(ssc COMPONENTS control) looks for the pure control law's packages only.
function(ssc_packages_of target out)
  set(_packages)
  get_target_property(_links ${target} LINK_LIBRARIES)
  foreach(l ${_links})
    if(l MATCHES "^([A-Za-z0-9_]+)::")
      list(APPEND _packages "${CMAKE_MATCH_1}")
    elseif(TARGET "${l}" AND l MATCHES "^ssc_")
      ssc_packages_of(${l} _inner)
      list(APPEND _packages ${_inner})
    endif()
  endforeach()
  list(REMOVE_DUPLICATES _packages)
  set(${out} "${_packages}" PARENT_SCOPE)
endfunction()
set(SSC_CONFIG_COMPONENT_PACKAGES "")  # set(_ssc_packages_<component> ...) lines for the config
set(SSC_CONFIG_COMPONENTS)
foreach(t ${SSC_EXPORTED_LIBRARIES})
  ssc_packages_of(${t} _packages)
  get_target_property(_component ${t} EXPORT_NAME)
  list(APPEND SSC_CONFIG_COMPONENTS ${_component})
  string(APPEND SSC_CONFIG_COMPONENT_PACKAGES
         "set(_ssc_packages_${_component} \"${_packages}\")\n")
endforeach()
set(SSC_CONFIG_PACKAGES)  # all of them (find_package(ssc) without components)
foreach(t ${SSC_EXPORTED_LIBRARIES})
  ssc_packages_of(${t} _packages)
  list(APPEND SSC_CONFIG_PACKAGES ${_packages})
endforeach()
list(REMOVE_DUPLICATES SSC_CONFIG_PACKAGES)

# Built against the PyPI wheel: its libmujoco goes into lib/ and its headers into include/ssc/
# (beside ours, on the same include path), so the prefix needs nothing of the builder's venv.
set(SSC_INSTALL_MUJOCO_LIBRARY "")
if(SSC_MUJOCO_LIBRARY)
  get_filename_component(_mujoco_name "${SSC_MUJOCO_LIBRARY}" NAME)
  set(SSC_INSTALL_MUJOCO_LIBRARY "${CMAKE_INSTALL_LIBDIR}/${_mujoco_name}")
  install(FILES "${SSC_MUJOCO_LIBRARY}" DESTINATION "${CMAKE_INSTALL_LIBDIR}")
  install(DIRECTORY "${SSC_MUJOCO_INCLUDE_DIR}/mujoco" DESTINATION "${SSC_INSTALL_INCLUDEDIR}")
endif()

if(SSC_INSTALL_MUJOCO_LIBRARY)
  set(SSC_CONFIG_MUJOCO_PATH_VARS SSC_INSTALL_MUJOCO_LIBRARY)
endif()
configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/sscConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/sscConfig.cmake" INSTALL_DESTINATION "${SSC_INSTALL_CMAKEDIR}"
  PATH_VARS SSC_INSTALL_DATADIR SSC_INSTALL_INCLUDEDIR ${SSC_CONFIG_MUJOCO_PATH_VARS})
write_basic_package_version_file("${PROJECT_BINARY_DIR}/sscConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/sscConfig.cmake" "${PROJECT_BINARY_DIR}/sscConfigVersion.cmake"
        DESTINATION "${SSC_INSTALL_CMAKEDIR}")
