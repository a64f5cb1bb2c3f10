# check_layering.cmake - fails when a module includes a header of a module it
# may not depend on (docs/architecture.md, "Modules"):
#
#   app -> eval -> pvs -> render -> scene -> base
#   predict -> base; every module above scene may use predict; scene and
#   predict do not use each other
#   shaders/ holds the headers shared by C and GLSL: render and above
#
# Usage: cmake -DROOT=<source tree> -P check_layering.cmake
# Each `#include "name"` of a module's .c/.cpp/.h/.glsl files is resolved to
# the module holding a file of that name (its own first); names found in no
# module (system, third-party, generated SPIR-V headers) are not checked.
cmake_minimum_required(VERSION 3.20)
if(NOT ROOT)
  message(FATAL_ERROR "check_layering: pass -DROOT=<source tree>")
endif()

set(modules base predict scene shaders render pvs eval app)
set(allowed_base base)
set(allowed_predict predict base)
set(allowed_scene scene base)
set(allowed_shaders shaders)
set(allowed_render render shaders scene predict base)
set(allowed_pvs pvs render shaders scene predict base)
set(allowed_eval eval pvs render shaders scene predict base)
set(allowed_app app eval pvs render shaders scene predict base)

foreach(m ${modules})
  file(GLOB files_${m} ${ROOT}/${m}/*.c ${ROOT}/${m}/*.cpp ${ROOT}/${m}/*.h ${ROOT}/${m}/*.glsl
       ${ROOT}/${m}/*.vert ${ROOT}/${m}/*.frag ${ROOT}/${m}/*.comp)
  set(names_${m})
  foreach(f ${files_${m}})
    get_filename_component(n ${f} NAME)
    list(APPEND names_${m} ${n})
  endforeach()
endforeach()

set(violations 0)
set(checked 0)
foreach(m ${modules})
  foreach(f ${files_${m}})
    file(STRINGS ${f} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    foreach(line ${lines})
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" inc "${line}")
      get_filename_component(n ${inc} NAME)
      set(owner "")
      if(n IN_LIST names_${m})
        set(owner ${m})
      else()
        foreach(o ${modules})
          if(n IN_LIST names_${o})
            set(owner ${o})
            break()
          endif()
        endforeach()
      endif()
      if(owner STREQUAL "")
        continue()
      endif()
      math(EXPR checked "${checked} + 1")
      if(NOT owner IN_LIST allowed_${m})
        file(RELATIVE_PATH rel ${ROOT} ${f})
        message(SEND_ERROR "${rel}: includes \"${inc}\" of ${owner}/, which ${m}/ may not use")
        math(EXPR violations "${violations} + 1")
      endif()
    endforeach()
  endforeach()
endforeach()
if(checked EQUAL 0)
  message(FATAL_ERROR "check_layering: no module includes found under ${ROOT}")
endif()
if(violations GREATER 0)
  message(FATAL_ERROR "check_layering: ${violations} include(s) against the dependency rule")
endif()
message(STATUS "check_layering: ${checked} module includes follow the dependency rule")
