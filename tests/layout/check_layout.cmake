# The dependency rule of docs/architecture.md, checked on the #include lines
# of a source tree:
#   - shared code (src/<folder> for the shared folders below, legacy_io/common,
#     palette/ and palette/window) includes no system's code;
#   - a system's code (src/<system>, legacy_io/<system>, palette/<system>,
#     src/cli/<system>, tests/*/<system>) includes shared code and its own;
#   - src/cli/*.cpp (the front end that registers every system's commands)
#     may include anything.
# A system is any folder of src/ that is not shared.
#   cmake -DROOT=<tree> -P check_layout.cmake
# Prints one line per violation and fails; prints a summary and succeeds
# otherwise. tests/CMakeLists.txt runs it on the repository and on fixture
# trees with deliberate violations (tests/layout/violation*).
cmake_minimum_required(VERSION 3.22)
if(NOT ROOT)
  message(FATAL_ERROR "usage: cmake -DROOT=<tree> -P check_layout.cmake")
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)
set(shared_src math geom render bench cli)

file(GLOB src_dirs RELATIVE ${ROOT}/src LIST_DIRECTORIES true ${ROOT}/src/*)
set(systems "")
foreach(d IN LISTS src_dirs)
  if(IS_DIRECTORY ${ROOT}/src/${d} AND NOT d IN_LIST shared_src)
    list(APPEND systems ${d})
  endif()
endforeach()

# owner(<path> <out>): the system a repository path belongs to, or "" (shared).
function(owner path out)
  set(result "")
  foreach(s IN LISTS systems)
    if(path MATCHES "^(src|legacy_io|palette|src/cli)/${s}/" OR path MATCHES "^tests/([a-z0-9_]+/)*${s}/")
      set(result ${s})
    endif()
  endforeach()
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

file(GLOB_RECURSE files RELATIVE ${ROOT}
     ${ROOT}/src/*.h ${ROOT}/src/*.cpp ${ROOT}/legacy_io/*.h ${ROOT}/legacy_io/*.cpp
     ${ROOT}/palette/*.h ${ROOT}/palette/*.cpp ${ROOT}/tests/unit/*.h ${ROOT}/tests/unit/*.cpp
     ${ROOT}/tests/e2e/*.h ${ROOT}/tests/e2e/*.cpp ${ROOT}/tests/fuzz/*.h ${ROOT}/tests/fuzz/*.cpp
     ${ROOT}/bench/*.h ${ROOT}/bench/*.cpp)
set(violations 0)
set(edges 0)
foreach(f IN LISTS files)
  if(f MATCHES "^src/cli/[^/]+$" OR f MATCHES "^bench/")
    continue()  # the front end and PRIME's microbenchmarks (bench/micro) see everything
  endif()
  owner(${f} from)
  file(STRINGS ${ROOT}/${f} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  set(n 0)
  file(STRINGS ${ROOT}/${f} all)
  foreach(line IN LISTS all)
    math(EXPR n "${n} + 1")
    if(NOT line MATCHES "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\"")
      continue()
    endif()
    set(inc ${CMAKE_MATCH_1})
    math(EXPR edges "${edges} + 1")
    owner(${inc} to)
    if(to STREQUAL "" OR to STREQUAL from)
      continue()
    endif()
    string(REGEX MATCH "^[a-z_]+/([a-z0-9_]+/)?" incdir "${inc}")
    if(from STREQUAL "")
      message("${f}:${n}: shared code includes ${incdir} (${inc}), code of the system '${to}'")
    else()
      message("${f}:${n}: the system '${from}' includes ${incdir} (${inc}), code of the system '${to}'")
    endif()
    math(EXPR violations "${violations} + 1")
  endforeach()
endforeach()
list(LENGTH files nfiles)
if(violations GREATER 0)
  message(FATAL_ERROR "layout: ${violations} include(s) break the dependency rule (docs/architecture.md)")
endif()
message("layout: ${edges} includes in ${nfiles} files keep the dependency rule (systems: ${systems})")
