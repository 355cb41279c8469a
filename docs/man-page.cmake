# SPDX-License-Identifier: MIT
# Builds litkit.1 with help2man from `litkit --help` and `litkit --version`,
# the text of docs/litkit.h2m, and a COMMANDS section written here: the
# `--help` of every command that `litkit --help` lists, so that the man page
# carries each command's options, not only the top level's. The list of
# commands is read from the program itself, so a new command appears without
# editing this.
#
#   cmake -DLITKIT=path/to/litkit -DHELP2MAN=help2man -DINCLUDE=litkit.h2m
#         -DOUTPUT=litkit.1 -P man-page.cmake

# The program runs under its own name (as help2man runs it), so that its
# usage lines read "litkit render", not the build path.
get_filename_component(program_dir ${LITKIT} DIRECTORY)
get_filename_component(program_name ${LITKIT} NAME)
set(ENV{PATH} "${program_dir}:$ENV{PATH}")

execute_process(COMMAND ${program_name} --help OUTPUT_VARIABLE top RESULT_VARIABLE status)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "${LITKIT} --help failed (${status})")
endif()
# The commands are the lines "  NAME   description" after "Subcommands:".
string(REGEX REPLACE ".*\nSubcommands:\n" "" listing "${top}")
string(REGEX MATCHALL "(^|\n)  [a-z][a-z0-9-]*" names "${listing}")
if(NOT names)
    message(FATAL_ERROR "no commands found in the output of '${LITKIT} --help'")
endif()

# roff: a section, then each command as a subsection whose help is kept as
# printed (.nf/.fi), with backslashes, minus signs and leading dots and
# quotes escaped.
set(text "[COMMANDS]\nEach command has options of its own, which \\fBlitkit\\fR \\fICOMMAND\\fR \\fB\\-\\-help\\fR prints:\n")
foreach(name IN LISTS names)
    string(STRIP "${name}" name)
    execute_process(COMMAND ${program_name} ${name} --help OUTPUT_VARIABLE help RESULT_VARIABLE status)
    if(NOT status EQUAL 0)
        message(FATAL_ERROR "${LITKIT} ${name} --help failed (${status})")
    endif()
    string(REPLACE "\\" "\\e" help "${help}")
    string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" help "${help}")
    string(REPLACE "-" "\\-" help "${help}")  # minus signs, not hyphens: options copy as typed
    string(APPEND text ".SS \"litkit ${name}\"\n.nf\n${help}.fi\n")
endforeach()
set(commands_include ${OUTPUT}-commands.h2m)
file(WRITE ${commands_include} "${text}")

# The COMMANDS section comes first among the sections help2man adds after
# OPTIONS, so its include goes first.
execute_process(COMMAND ${HELP2MAN} --no-info --section=1
                        "--name=render lit, shaded 3D scenes from scene files"
                        --include=${commands_include} --include=${INCLUDE}
                        --output=${OUTPUT} ${program_name}
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "help2man failed (${status})")
endif()
