# Man pages of the hydrocoef CLI, made from its own --help (cmake -P, at build time):
#   cmake -DHYDROCOEF_CLI=path/to/hydrocoef -DOUTPUT_DIR=dir -DVERSION=0.1.0 -P cmake/man_pages.cmake
# writes OUTPUT_DIR/hydrocoef.1 (the program, its global options and the list of commands) and one page per
# command, OUTPUT_DIR/hydrocoef-COMMAND.1, holding `hydrocoef COMMAND --help` and the help of each of its
# subcommands (surface build, plot fit, ...). The commands are read from `hydrocoef --help`, so a new command
# gets its page without a change here. The help text is set as it is printed (.nf), with roff's special
# characters escaped; no date is written, so the pages are the same in every build of one version.
cmake_minimum_required(VERSION 3.18)

foreach(required HYDROCOEF_CLI OUTPUT_DIR VERSION)
  if(NOT DEFINED ${required})
    message(FATAL_ERROR "man_pages.cmake: -D${required}=... is required")
  endif()
endforeach()

# `hydrocoef ARGS... --help` as text; a failure stops the build.
function(help_text out)
  execute_process(COMMAND ${HYDROCOEF_CLI} ${ARGN} --help OUTPUT_VARIABLE text ERROR_VARIABLE error
                  RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    list(JOIN ARGN " " words)
    message(FATAL_ERROR "man_pages.cmake: 'hydrocoef ${words} --help' failed (${result}): ${error}")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# The names listed under "Subcommands:" in a help text (CLI11 prints each indented, then its description).
function(subcommands_of text out)
  string(REPLACE ";" "\\;" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(names "")
  set(inside FALSE)
  foreach(line IN LISTS lines)
    if(line MATCHES "^(SUBCOMMANDS|Subcommands):")
      set(inside TRUE)
    elseif(inside AND line MATCHES "^  ([a-z][a-z0-9-]*)( |$)")
      list(APPEND names ${CMAKE_MATCH_1})
    elseif(inside AND NOT line MATCHES "^ " AND NOT line STREQUAL "")
      set(inside FALSE)
    endif()
  endforeach()
  set(${out} ${names} PARENT_SCOPE)
endfunction()

# A command's description in its parent's help ("  import   Import CFD results ...").
function(description_of parent_text name out)
  set(description "")
  string(REGEX MATCH "\n  ${name}  +([^\n]*)" match "${parent_text}")
  if(match)
    set(description "${CMAKE_MATCH_1}")
    # Its first clause, for the one-line NAME section (the whole text is in DESCRIPTION).
    string(REGEX REPLACE "(: |; | \\().*$" "" description "${description}")
  endif()
  set(${out} "${description}" PARENT_SCOPE)
endfunction()

# Text made inert for roff: backslashes escaped, a line starting with '.' or ''' kept as text, '-' as a
# minus sign (so options can be searched for and copied).
function(roff_text text out)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REPLACE "-" "\\-" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

function(write_page file title name description body see_also)
  roff_text("${description}" description)
  string(TOUPPER "${title}" upper)
  set(page ".\\\" Made by cmake/man_pages.cmake from the program's --help; do not edit.\n")
  string(APPEND page ".TH \"${upper}\" 1 \"\" \"hydrocoef ${VERSION}\" \"User Commands\"\n")
  string(APPEND page ".SH NAME\n${name} \\- ${description}\n")
  string(APPEND page "${body}")
  string(APPEND page ".SH SEE ALSO\n${see_also}\n")
  file(WRITE "${OUTPUT_DIR}/${file}" "${page}")
endfunction()

function(help_section heading text out)
  roff_text("${text}" text)
  set(${out} ".SH ${heading}\n.nf\n${text}\n.fi\n" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE "${OUTPUT_DIR}")
file(MAKE_DIRECTORY "${OUTPUT_DIR}")

help_text(top)
subcommands_of("${top}" commands)
if(NOT commands)
  message(FATAL_ERROR "man_pages.cmake: no commands found in 'hydrocoef --help'")
endif()

set(pages "")
foreach(command IN LISTS commands)
  help_text(text ${command})
  help_section("DESCRIPTION" "${text}" body)
  subcommands_of("${text}" subcommands)
  foreach(subcommand IN LISTS subcommands)
    help_text(sub_text ${command} ${subcommand})
    string(TOUPPER "${command} ${subcommand}" heading)
    help_section("\"${heading}\"" "${sub_text}" section)
    string(APPEND body "${section}")
  endforeach()
  description_of("${top}" ${command} description)
  string(REPLACE "-" "\\-" roff_command "${command}")
  write_page("hydrocoef-${command}.1" "hydrocoef-${command}" "hydrocoef\\-${roff_command}" "${description}"
             "${body}" ".BR hydrocoef (1)")
  list(APPEND pages ".BR hydrocoef\\-${roff_command} (1)")
endforeach()

help_section("DESCRIPTION" "${top}" body)
string(APPEND body ".SH COMMANDS\nEach command has a page of its own, \\fBhydrocoef\\-COMMAND\\fR(1), "
       "and prints the same with \\fBhydrocoef COMMAND \\-\\-help\\fR.\n")
string(APPEND body ".SH EXIT STATUS\n0 on success; 2 for bad input or usage (one line on standard error naming "
       "the file and line, what was found and what was expected; the database is left as it was); 1 for an "
       "internal error.\n")
list(JOIN pages ",\n" see_also)
write_page("hydrocoef.1" "hydrocoef" "hydrocoef" "CFD results to hydrodynamic coefficient databases"
           "${body}" "${see_also}")
