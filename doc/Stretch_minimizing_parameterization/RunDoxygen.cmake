# Runs Doxygen on the package documentation and fails on any warning, or if an example of
# examples/Stretch_minimizing_parameterization/ is missing from examples.txt or the manual.
#   cmake -DDOXYGEN=<doxygen> -DSOURCE_DIR=<this directory> -DOUTPUT_DIR=<build directory> -P RunDoxygen.cmake
#
# Pictures are optional: the manual shows fig/<name>.png inside `\if fig_<name>` ... `\endif`,
# and the section fig_<name> is enabled here only when that file exists, at build time. A
# picture not yet made leaves no dead link and no warning.

foreach(variable DOXYGEN SOURCE_DIR OUTPUT_DIR)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "RunDoxygen.cmake: -D${variable}=... is required")
  endif()
endforeach()

# Every example must be listed in examples.txt and shown in the manual.
file(READ ${SOURCE_DIR}/examples.txt examples_txt)
file(READ ${SOURCE_DIR}/Stretch_minimizing_parameterization.txt manual_txt)
file(GLOB examples RELATIVE ${SOURCE_DIR}/../../examples
     ${SOURCE_DIR}/../../examples/Stretch_minimizing_parameterization/*.cpp)
set(unlisted "")
foreach(example IN LISTS examples)
  string(FIND "${examples_txt}" "\\example ${example}" in_list)
  string(FIND "${manual_txt}" "\\cgalExample{${example}}" in_manual)
  if(in_list EQUAL -1 OR in_manual EQUAL -1)
    list(APPEND unlisted ${example})
  endif()
endforeach()
if(unlisted)
  message(FATAL_ERROR "Examples missing from examples.txt (\\example) or from the manual "
                      "(\\cgalExample{...}): ${unlisted}")
endif()

file(GLOB pictures RELATIVE ${SOURCE_DIR}/fig ${SOURCE_DIR}/fig/*.png)
list(SORT pictures)
set(sections "")
foreach(picture IN LISTS pictures)
  string(REGEX REPLACE "\\.png$" "" name "${picture}")
  string(MAKE_C_IDENTIFIER "fig_${name}" section)
  list(APPEND sections ${section})
endforeach()
list(JOIN sections " " sections)

file(MAKE_DIRECTORY ${OUTPUT_DIR})
set(log ${OUTPUT_DIR}/doxygen_warnings.log)
file(REMOVE ${log})
file(WRITE ${OUTPUT_DIR}/Doxyfile.build
  "@INCLUDE         = ${SOURCE_DIR}/Doxyfile\n"
  "OUTPUT_DIRECTORY = ${OUTPUT_DIR}\n"
  "WARN_LOGFILE     = ${log}\n"
  "ENABLED_SECTIONS = ${sections}\n")

# Doxygen runs bibtex in OUTPUT_DIR on files it writes there; Debian's bibtex finds them only
# if the current directory is in its search paths.
set(ENV{BSTINPUTS} ".:$ENV{BSTINPUTS}")
set(ENV{BIBINPUTS} ".:$ENV{BIBINPUTS}")

# The Doxyfile's paths are relative to SOURCE_DIR.
execute_process(COMMAND ${DOXYGEN} ${OUTPUT_DIR}/Doxyfile.build
                WORKING_DIRECTORY ${SOURCE_DIR}
                RESULT_VARIABLE status)

set(warnings "")
if(EXISTS ${log})
  file(READ ${log} warnings)
  string(STRIP "${warnings}" warnings)
endif()
if(NOT warnings STREQUAL "")
  message("${warnings}")
  message(FATAL_ERROR "Doxygen warnings (see above, and ${log}): the documentation must build without any.")
endif()
if(NOT status EQUAL 0)
  message(FATAL_ERROR "Doxygen failed (exit status ${status}).")
endif()
if(sections STREQUAL "")
  message(STATUS "No picture in ${SOURCE_DIR}/fig: the manual is built without figures")
else()
  message(STATUS "Figures shown: ${pictures}")
endif()
message(STATUS "Documentation: ${OUTPUT_DIR}/html/index.html (0 Doxygen warnings)")
