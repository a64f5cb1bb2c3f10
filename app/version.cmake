# Writes OUT with TRIMVR_VERSION: PROJECT_VERSION plus `git describe` of SRC
# (commit, -dirty with uncommitted changes), or "-nogit" outside a checkout.
# Run at every build; the file is rewritten only when the text changes, so
# nothing recompiles without a new version. Bench part files carry it.
execute_process(COMMAND git describe --always --dirty --tags WORKING_DIRECTORY ${SRC}
                OUTPUT_VARIABLE describe OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc ERROR_QUIET)
if(NOT rc EQUAL 0 OR describe STREQUAL "")
  set(describe "nogit")
endif()
set(text "#define TRIMVR_VERSION \"${PROJECT_VERSION}-${describe}\"\n")
set(old "")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUT} "${text}")
endif()
