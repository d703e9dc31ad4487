# Writes fatek-cli's shell completions (cmake -DPROGRAM=... -DOUT=dir -P writecompletions.cmake).
file(MAKE_DIRECTORY ${OUT})
foreach(shell bash zsh)
    if(shell STREQUAL "bash")
        set(file ${OUT}/fatek-cli)
    else()
        set(file ${OUT}/_fatek-cli)
    endif()
    execute_process(COMMAND ${PROGRAM} --completion ${shell} OUTPUT_FILE ${file}
                    RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "${PROGRAM} --completion ${shell} failed: ${rc}")
    endif()
endforeach()
