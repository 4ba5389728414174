# The architecture check (docs/architecture.md): fails when a file of a part includes a header of a
# part that is not below it.
#
#   cmake -DPART_TABLE=<parts.cmake> -DSOURCE_ROOT=<dir holding the part folders> -P <this file>
#
# PART_TABLE sets ANCFNET_PARTS (lowest first) and ANCFNET_PART_<part>_DEPENDS (written by
# ancfnet_write_part_table). A file under SOURCE_ROOT/<part>/, outside test/ folders, may include
# "ancfnet/<other>/..." only when <other> is <part> or reachable from it through DEPENDS. Every
# folder of SOURCE_ROOT holding sources must be a declared part. Unit tests (test/ folders) are
# exempt: they link the whole library and may build scenes through io/.
cmake_minimum_required(VERSION 3.25)
foreach(variable PART_TABLE SOURCE_ROOT)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "check_architecture: pass -D${variable}=...")
  endif()
endforeach()
include("${PART_TABLE}")
get_filename_component(SOURCE_ROOT "${SOURCE_ROOT}" ABSOLUTE)

# Parts each part may include: itself and the transitive closure of its DEPENDS. The table lists
# the parts lowest first, so a part's dependencies are complete when it is reached.
foreach(part IN LISTS ANCFNET_PARTS)
  set(allowed_${part} ${part})
  foreach(dependency IN LISTS ANCFNET_PART_${part}_DEPENDS)
    list(APPEND allowed_${part} ${allowed_${dependency}})
  endforeach()
  list(REMOVE_DUPLICATES allowed_${part})
endforeach()

set(violations "")
file(GLOB folders LIST_DIRECTORIES true RELATIVE "${SOURCE_ROOT}" "${SOURCE_ROOT}/*")
foreach(folder IN LISTS folders)
  if(NOT IS_DIRECTORY "${SOURCE_ROOT}/${folder}")
    continue()
  endif()
  file(GLOB_RECURSE files "${SOURCE_ROOT}/${folder}/*.hpp" "${SOURCE_ROOT}/${folder}/*.cpp")
  list(FILTER files EXCLUDE REGEX "/test/")
  if(NOT files)
    continue()
  endif()
  if(NOT folder IN_LIST ANCFNET_PARTS)
    string(APPEND violations "  ${folder}/ is not a declared part: give it a CMakeLists.txt "
                             "calling ancfnet_add_part and add it to ANCFNET_LAYERS in layer "
                             "order\n")
    continue()
  endif()
  foreach(file IN LISTS files)
    file(STRINGS "${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]ancfnet/")
    foreach(line IN LISTS includes)
      string(REGEX MATCH "ancfnet/([A-Za-z0-9_]+)/" match "${line}")
      set(included "${CMAKE_MATCH_1}")
      if(included AND NOT included IN_LIST allowed_${folder})
        file(RELATIVE_PATH relative "${SOURCE_ROOT}" "${file}")
        string(STRIP "${line}" line)
        string(REPLACE ";" ", " allowed "${allowed_${folder}}")
        string(APPEND violations
               "  ${relative}: ${line} (part '${folder}' may include only: ${allowed})\n")
      endif()
    endforeach()
  endforeach()
endforeach()

if(violations)
  message(FATAL_ERROR "architecture check: includes that run against the layering "
                      "(docs/architecture.md):\n${violations}")
endif()
list(LENGTH ANCFNET_PARTS num_parts)
message(STATUS "architecture check: ${num_parts} parts, every include points down")
