# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
# cmake -DMEFF=... -DSCENE=... -DOUTPUT_DIR=... -P check_run_scene.cmake
# Passes when `meff run SCENE` with all three CSV outputs exits with status 0, prints its
# one-line summary, and each file starts with its header and has data rows where data must be.
file(REMOVE_RECURSE ${OUTPUT_DIR})
file(MAKE_DIRECTORY ${OUTPUT_DIR})
execute_process(COMMAND ${MEFF} run ${SCENE}
        --trajectory ${OUTPUT_DIR}/trajectory.csv
        --contacts ${OUTPUT_DIR}/contacts.csv
        --joints ${OUTPUT_DIR}/joints.csv
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status STREQUAL "0")
    message(FATAL_ERROR "exit status ${status}\n${out}${err}")
endif()
if(NOT out MATCHES "^[A-Za-z0-9_.-]+: [0-9]+ bodies, [0-9]+ joints, [0-9]+ frames .* in [0-9.]+ s\n$")
    message(FATAL_ERROR "unexpected summary: ${out}")
endif()
foreach(pair IN ITEMS
        "trajectory|frame,time,body,x,y,angle,vx,vy,omega"
        "contacts|frame,body_a,body_b,point,px,py,nx,ny,normal_impulse,tangent_impulse"
        "joints|frame,joint,fx,fy,torque")
    string(REPLACE "|" ";" pair "${pair}")
    list(GET pair 0 kind)
    list(GET pair 1 header)
    file(STRINGS ${OUTPUT_DIR}/${kind}.csv lines)
    list(GET lines 0 first)
    if(NOT first STREQUAL header)
        message(FATAL_ERROR "${kind}.csv starts with '${first}', expected '${header}'")
    endif()
endforeach()
# Frame 0 of the trajectory is the initial state: at least one row for it.
file(STRINGS ${OUTPUT_DIR}/trajectory.csv frame0 REGEX "^0,0,")
if(frame0 STREQUAL "")
    message(FATAL_ERROR "trajectory.csv has no frame 0")
endif()
# No temporary file may be left behind.
file(GLOB leftovers ${OUTPUT_DIR}/.*)
if(leftovers)
    message(FATAL_ERROR "temporary files left: ${leftovers}")
endif()
