# Unity groups: a target's sources compiled a few at a time as one
# translation unit (CMake's UNITY_BUILD in GROUP mode), files of one folder
# together in order, at most HYDROCOEF_UNITY_GROUP_SIZE a group. The headers,
# templates and inline functions (JSON, Eigen, the standard library) they
# share are parsed, instantiated and optimized once a group instead of once
# a file: a fresh build of the library takes a third less CPU. Off by
# default (a change to one file recompiles its group); scripts/build.sh turns
# it on for the test and optimized builds, the ones every test run makes.
#
# A group is a translation unit: names at namespace scope of one file (also
# in anonymous namespaces) must not clash with another file of its group.
# Files given after EXCLUDE are compiled alone (their own flags, or names
# that would clash).
option(HYDROCOEF_UNITY_BUILD "Compile the library, CLI and Python module sources in unity groups" OFF)
set(HYDROCOEF_UNITY_GROUP_SIZE 6 CACHE STRING "Most sources in one unity group")

# hydrocoef_unity_groups(TARGET SOURCES... [EXCLUDE SOURCES...]): call from
# the directory that made TARGET.
function(hydrocoef_unity_groups target)
  if(NOT HYDROCOEF_UNITY_BUILD)
    return()
  endif()
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "EXCLUDE")
  set(excluded "")
  foreach(source ${arg_EXCLUDE})
    get_filename_component(source ${source} ABSOLUTE)
    list(APPEND excluded ${source})
  endforeach()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
  foreach(source ${arg_UNPARSED_ARGUMENTS})
    get_filename_component(source ${source} ABSOLUTE)
    if(source IN_LIST excluded)
      continue()
    endif()
    get_filename_component(folder ${source} DIRECTORY)
    file(RELATIVE_PATH folder ${PROJECT_SOURCE_DIR} ${folder})
    string(MAKE_C_IDENTIFIER "${target}_${folder}" id)
    if(NOT DEFINED count_${id})
      set(count_${id} 0)
    endif()
    math(EXPR group "${count_${id}} / ${HYDROCOEF_UNITY_GROUP_SIZE}")
    math(EXPR count_${id} "${count_${id}} + 1")
    set_source_files_properties(${source} PROPERTIES UNITY_GROUP "${id}_${group}")
  endforeach()
endfunction()
