# SPDX-License-Identifier: MIT
# Writes OUTPUT from `LITKIT --bash-completion` (docs/CMakeLists.txt).
execute_process(COMMAND ${LITKIT} --bash-completion OUTPUT_FILE ${OUTPUT}.tmp RESULT_VARIABLE failed)
if(failed)
    message(FATAL_ERROR "${LITKIT} --bash-completion failed: ${failed}")
endif()
file(RENAME ${OUTPUT}.tmp ${OUTPUT})
