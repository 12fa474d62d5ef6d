# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
# cmake -DMEFF=... -DSCENE=... -DOUTPUT_DIR=... -P check_render_scene.cmake
# Passes when `meff render SCENE` (4 steps, every 2nd frame, small, every overlay on) exits with
# status 0 and writes exactly frame_00000.png to frame_00002.png and nothing else, and when the
# same command run again writes byte-identical files. -DNO_OVERLAY=ON leaves out --overlay-box2d
# (Box2D 2.4.1 cannot run the scenes of samples/v3 beside meff).
set(overlay --overlay-box2d)
if(NO_OVERLAY)
    set(overlay)
endif()
foreach(run IN ITEMS a b)
    file(REMOVE_RECURSE ${OUTPUT_DIR}/${run})
    execute_process(COMMAND ${MEFF} render ${SCENE} --out ${OUTPUT_DIR}/${run} --frames 4 --every 2
            --size 160x120 --contacts --impulses --joints ${overlay}
        RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT status STREQUAL "0")
        message(FATAL_ERROR "exit status ${status}\n${out}${err}")
    endif()
    file(GLOB written RELATIVE ${OUTPUT_DIR}/${run} ${OUTPUT_DIR}/${run}/* ${OUTPUT_DIR}/${run}/.*)
    list(REMOVE_DUPLICATES written)
    list(SORT written)
    if(NOT written STREQUAL "frame_00000.png;frame_00001.png;frame_00002.png")
        message(FATAL_ERROR "wrote '${written}', expected frame_00000.png to frame_00002.png")
    endif()
endforeach()
foreach(frame IN ITEMS 00000 00001 00002)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files
            ${OUTPUT_DIR}/a/frame_${frame}.png ${OUTPUT_DIR}/b/frame_${frame}.png
        RESULT_VARIABLE different)
    if(different)
        message(FATAL_ERROR "frame_${frame}.png differs between two identical runs")
    endif()
endforeach()
