# Writes OUTPUT, a C++ file defining frictionlab::git_revision(), from `git describe` of SOURCE_DIR
# (run at every build, so `frictionlab --version` names the commit it was built from). The file is
# rewritten only when the revision changes, so an unchanged tree relinks nothing.
execute_process(COMMAND git -C "${SOURCE_DIR}" describe --always --dirty --abbrev=12
                OUTPUT_VARIABLE revision OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE failed)
if(failed OR revision STREQUAL "")
  set(revision "unknown")  # a source archive without git history
endif()
set(text "#include \"frictionlab/base/version.hpp\"\n\nstd::string frictionlab::git_revision() { return \"${revision}\"; }\n")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUTPUT}" "${text}")
endif()
