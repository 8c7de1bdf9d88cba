# cmake -DBINARY=<file> -DREADELF=<readelf> -DFORBIDDEN=<name;...> -P CheckNeededLibraries.cmake
# Fails when the ELF file BINARY needs (DT_NEEDED) a shared library lib<name>... for a name of FORBIDDEN.
cmake_minimum_required(VERSION 3.25)
execute_process(COMMAND ${READELF} -d ${BINARY} OUTPUT_VARIABLE dynamic RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "${READELF} -d ${BINARY} failed")
endif()
foreach(name IN LISTS FORBIDDEN)
  if(dynamic MATCHES "\\(NEEDED\\)[^\n]*\\[(lib${name}[^]]*)\\]")
    message(FATAL_ERROR "${BINARY} needs ${CMAKE_MATCH_1}; it must not (cmake/CycloptModules.cmake, cyclopt_forbid_needed)")
  endif()
endforeach()
