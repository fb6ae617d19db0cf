# SPDX-License-Identifier: Apache-2.0
# dda_write_link_graph(FILE): every target the project defines, one line each:
#   NAME <tab> TYPE <tab> HOME <tab> MARK <tab> DEP;DEP;...
# HOME is the first folder of the directory that defines it (model, host, tb, cli, tests,
# bench, python), MARK the target's DDA_LINKS_TEST_BENCH property (empty if not set), DEP
# its direct links (LINK_LIBRARIES and INTERFACE_LINK_LIBRARIES; imported and system
# libraries included, $<LINK_ONLY:...> unwrapped). tests/check-layout.py reads it and
# checks the direction the homes link in.
function(_dda_collect_targets dir out)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    _dda_collect_targets(${sub} more)
    list(APPEND targets ${more})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

function(dda_write_link_graph file)
  _dda_collect_targets(${PROJECT_SOURCE_DIR} targets)
  set(text "")
  foreach(t IN LISTS targets)
    get_target_property(type ${t} TYPE)
    get_target_property(src ${t} SOURCE_DIR)
    file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${src})
    string(REGEX REPLACE "/.*" "" home "${rel}")
    if(home STREQUAL "")
      set(home ".")
    endif()
    get_target_property(mark ${t} DDA_LINKS_TEST_BENCH)
    if(NOT mark)
      set(mark "")
    endif()
    set(deps "")
    if(NOT type STREQUAL "INTERFACE_LIBRARY")
      get_target_property(l ${t} LINK_LIBRARIES)
      if(l)
        list(APPEND deps ${l})
      endif()
    endif()
    get_target_property(il ${t} INTERFACE_LINK_LIBRARIES)
    if(il)
      list(APPEND deps ${il})
    endif()
    list(TRANSFORM deps REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1")
    list(REMOVE_DUPLICATES deps)
    string(REPLACE "\t" " " mark "${mark}")
    string(APPEND text "${t}\t${type}\t${home}\t${mark}\t${deps}\n")
  endforeach()
  file(WRITE ${file}.new "${text}")
  # Rewritten only when it changes, so that reconfiguring does not touch it.
  file(COPY_FILE ${file}.new ${file} ONLY_IF_DIFFERENT)
  file(REMOVE ${file}.new)
endfunction()
