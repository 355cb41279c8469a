# SPDX-License-Identifier: MIT
# Finds what the Python module needs (docs/python.md): a Python 3 interpreter
# with NumPy, its headers, and pybind11. Sets LITKIT_PYTHON_FOUND.
#
# The module is built for one interpreter. Unless -DPython3_EXECUTABLE= names
# one, that is the first of `python3` on PATH and Debian's /usr/bin/python3
# that can import NumPy: scripts/install-deps.sh installs python3-numpy for
# the latter, and a python3 of pyenv or a virtualenv earlier on PATH without
# NumPy must not make the option silently off.
if(NOT Python3_EXECUTABLE)
    find_program(LITKIT_PYTHON3_ON_PATH python3)
    foreach(candidate IN ITEMS "${LITKIT_PYTHON3_ON_PATH}" /usr/bin/python3)
        if(candidate AND EXISTS "${candidate}")
            execute_process(COMMAND "${candidate}" -c "import numpy"
                            RESULT_VARIABLE numpy_missing OUTPUT_QUIET ERROR_QUIET)
            if(numpy_missing EQUAL 0)
                set(Python3_EXECUTABLE "${candidate}" CACHE FILEPATH
                    "The Python interpreter litkit's Python module is built for")
                break()
            endif()
        endif()
    endforeach()
endif()
set(LITKIT_PYTHON_FOUND OFF)
find_package(Python3 3.8 QUIET COMPONENTS Interpreter Development.Module NumPy)
if(Python3_FOUND AND Python3_NumPy_FOUND)
    # pybind11 uses the Python3 found above (its "new FindPython mode").
    find_package(pybind11 2.6 QUIET CONFIG)
    if(pybind11_FOUND)
        set(LITKIT_PYTHON_FOUND ON)
    endif()
endif()
if(LITKIT_PYTHON_FOUND)
    message(STATUS "litkit: Python module for ${Python3_EXECUTABLE} "
                   "(NumPy ${Python3_NumPy_VERSION}, pybind11 ${pybind11_VERSION})")
else()
    message(STATUS "litkit: no Python module: pybind11, or a Python 3 with NumPy and its headers, "
                   "not found (scripts/install-deps.sh installs them)")
endif()
