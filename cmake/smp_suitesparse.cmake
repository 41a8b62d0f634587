# One SuiteSparse library for the package's target, optional: when its header and library are
# found, TARGET defines DEFINITION (the macro that makes the headers use it), sees the header and
# links the library; FOUND receives whether it was. Used by the build tree (for BUILD_INTERFACE only: the paths of this
# machine are not exported) and by the installed package config, which finds them again.
function(smp_use_suitesparse TARGET NAME HEADER LIBRARY DEFINITION FOUND)
  find_path(SMP_${NAME}_INCLUDE_DIR ${HEADER} PATH_SUFFIXES suitesparse)
  find_library(SMP_${NAME}_LIBRARY ${LIBRARY})
  if(NOT (SMP_${NAME}_INCLUDE_DIR AND SMP_${NAME}_LIBRARY))
    set(${FOUND} FALSE PARENT_SCOPE)
    return()
  endif()
  get_target_property(imported ${TARGET} IMPORTED)
  if(imported)
    target_compile_definitions(${TARGET} INTERFACE ${DEFINITION})
    target_include_directories(${TARGET} INTERFACE ${SMP_${NAME}_INCLUDE_DIR})
    target_link_libraries(${TARGET} INTERFACE ${SMP_${NAME}_LIBRARY})
  else()
    target_compile_definitions(${TARGET} INTERFACE $<BUILD_INTERFACE:${DEFINITION}>)
    target_include_directories(${TARGET} INTERFACE $<BUILD_INTERFACE:${SMP_${NAME}_INCLUDE_DIR}>)
    target_link_libraries(${TARGET} INTERFACE $<BUILD_INTERFACE:${SMP_${NAME}_LIBRARY}>)
  endif()
  set(${FOUND} TRUE PARENT_SCOPE)
endfunction()
