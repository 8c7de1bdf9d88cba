# cyclopt_link_closure(<out-var> <target>): the cyclopt modules <target> links, directly or through
# other modules ("foot;autodiff;errors" for cyclopt_io's foot part), from its link properties.
function(cyclopt_link_closure out target)
  set(closure "")
  set(pending ${target})
  while(pending)
    list(POP_FRONT pending t)
    get_target_property(type ${t} TYPE)
    if(type STREQUAL "INTERFACE_LIBRARY")
      get_target_property(links ${t} INTERFACE_LINK_LIBRARIES)
    else()
      get_target_property(links ${t} LINK_LIBRARIES)
    endif()
    foreach(link IN LISTS links)
      if(link MATCHES "^cyclopt_(.+)$" AND NOT CMAKE_MATCH_1 IN_LIST closure)
        list(APPEND closure ${CMAKE_MATCH_1})
        list(APPEND pending ${link})
      endif()
    endforeach()
  endwhile()
  set(${out} "${closure}" PARENT_SCOPE)
endfunction()

# cyclopt_forbid_links(<target> <module>...): fails the configure step when <target> links one of
# the modules, however indirectly.
function(cyclopt_forbid_links target)
  cyclopt_link_closure(closure ${target})
  foreach(module IN LISTS ARGN)
    if(module IN_LIST closure)
      message(FATAL_ERROR "${target} must not link cyclopt_${module} (it links: ${closure})")
    endif()
  endforeach()
endfunction()

# cyclopt_forbid_needed(<target> <library>...): after <target> is linked, fails the build when its
# dynamic section needs a shared library whose name begins with one of <library> ("ipopt":
# libipopt.so.1). The target links with --as-needed, so a library is needed only where its code is used.
function(cyclopt_forbid_needed target)
  target_link_options(${target} PRIVATE LINKER:--as-needed)
  if(NOT CMAKE_READELF)
    message(STATUS "${target}: no readelf, its needed libraries are not checked")
    return()
  endif()
  add_custom_command(TARGET ${target} POST_BUILD
    COMMAND ${CMAKE_COMMAND} -DBINARY=$<TARGET_FILE:${target}> -DREADELF=${CMAKE_READELF} "-DFORBIDDEN=${ARGN}"
            -P ${PROJECT_SOURCE_DIR}/cmake/CheckNeededLibraries.cmake
    VERBATIM)
endfunction()
