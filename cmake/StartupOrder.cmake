# Start-up time of the program. The dynamic linker resolves each library's references to its own exported
# symbols by searching every library loaded before it, in load order; GDAL's large C++ dependencies
# (Xerces-C, GEOS, OpenSSL's libcrypto, Poppler, libkml, SQLite, netCDF, LAPACK, HDF5, PROJ) load behind
# about a hundred others. Named first by the program, they load first: about 8 ms less at every start on
# Debian 12 (docs/benchmarks.md, 2026-11-26 seventh session). Only libraries GDAL loads anyway are named,
# as the loader finds them (ldd); where ldd or one of them is missing the program links as before.
function(mcpp_link_gdal_dependencies_first target)
  get_target_property(gdal_library GDAL::GDAL IMPORTED_LOCATION_RELEASE)
  if(NOT gdal_library)
    get_target_property(gdal_library GDAL::GDAL IMPORTED_LOCATION_NONE)
  endif()
  if(NOT gdal_library)
    get_target_property(gdal_library GDAL::GDAL IMPORTED_LOCATION)
  endif()
  find_program(MCPP_LDD ldd)
  if(NOT gdal_library OR NOT MCPP_LDD)
    return()
  endif()
  execute_process(COMMAND ${MCPP_LDD} ${gdal_library} OUTPUT_VARIABLE loaded ERROR_QUIET RESULT_VARIABLE failed)
  if(failed)
    return()
  endif()
  set(first)
  foreach(name libxerces-c libgeos libcrypto libpoppler libkmldom libsqlite3 libnetcdf liblapack
          libhdf5_serial libproj)
    string(REGEX MATCH "${name}[-.][^ \t]* => ([^ \t]+)" found "${loaded}")
    if(found AND IS_ABSOLUTE "${CMAKE_MATCH_1}" AND EXISTS "${CMAKE_MATCH_1}") # not "=> not found"
      list(APPEND first ${CMAKE_MATCH_1})
    endif()
  endforeach()
  # Called before the target's other links, so that these come first on the link line; kept although the
  # program calls none of them (the toolchain links as needed).
  target_link_libraries(${target} PRIVATE -Wl,--push-state,--no-as-needed ${first} -Wl,--pop-state)
endfunction()
