# cmake -DSRC=DIR -DOUT=FILE "-DSETTINGS=..." -P gw_build_id.cmake: the build's
# identity a sweep journal records (common/sweep/gw_sweep_build.c): the git
# commit of the source (when it is a git checkout and git is there; "+" when
# tracked files differ from it) and the compile settings that can change
# results. Run at every build, not at configure time: a commit made since the
# configure changes it. FILE is rewritten only when it changes, so an
# unchanged build recompiles nothing.
set(commit "")
set(local 0)
find_package(Git QUIET)
if(GIT_FOUND AND EXISTS "${SRC}/.git")
  execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${SRC}" rev-parse --short=12 HEAD
                  OUTPUT_VARIABLE commit RESULT_VARIABLE rc OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT rc EQUAL 0)
    set(commit "")
  endif()
  if(commit)
    execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${SRC}" status --porcelain --untracked-files=no
                    OUTPUT_VARIABLE changed RESULT_VARIABLE rc ERROR_QUIET)
    if(NOT rc EQUAL 0 OR NOT changed STREQUAL "")
      set(local 1)
    endif()
  endif()
endif()
string(REPLACE "\\" "\\\\" SETTINGS "${SETTINGS}")
string(REPLACE "\"" "\\\"" SETTINGS "${SETTINGS}")
string(REGEX REPLACE "  +" " " SETTINGS "${SETTINGS}")
string(STRIP "${SETTINGS}" SETTINGS)
set(text "/* Generated at every build by cmake/gw_build_id.cmake: the build a sweep journal records. */
#define GW_BUILD_COMMIT \"${commit}\"
#define GW_BUILD_LOCAL_CHANGES ${local}
#define GW_BUILD_SETTINGS \"${SETTINGS}\"
")
file(WRITE "${OUT}.new" "${text}")
configure_file("${OUT}.new" "${OUT}" COPYONLY)
file(REMOVE "${OUT}.new")
