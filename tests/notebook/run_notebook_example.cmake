# SPDX-License-Identifier: MIT
# Fits the bundled reference data over Q0-1 x S0-1 (60 live points: well under a second), runs the
# notebook example on the result, and checks both figures: the pixel size the script promises, a file
# size no blank figure reaches (20 kB: a blank 800x800 Matplotlib PNG has 4.4 kB, the Q1S1 corner plot
# about 130 kB, the band plot about 38 kB), and non-empty rows (tests/report/check_png.py).
include(${CMAKE_CURRENT_LIST_DIR}/../script_support.cmake)
require_variables(ADMITGEN_EXE PYTHON SOURCE_DIR WORK_DIR)
file(REMOVE_RECURSE "${WORK_DIR}")
run("${ADMITGEN_EXE}" fit "${SOURCE_DIR}/samples/reference/q1s1_sigma0.01.csv" --qmax 1 --smax 1 --live 60 --seed 2
    --quiet --out "${WORK_DIR}/fit")
run(${CMAKE_COMMAND} -E env MPLBACKEND=Agg "${PYTHON}" "${SOURCE_DIR}/samples/notebook/corner_plot.py"
    "${WORK_DIR}/fit/fit.json" "${WORK_DIR}/figures")
message(STATUS "${out}")
foreach(figure corner predictive)
  set(png "${WORK_DIR}/figures/${figure}.png")
  file(SIZE "${png}" bytes)
  if(bytes LESS 20000)
    message(FATAL_ERROR "${png} has only ${bytes} bytes: an empty figure?")
  endif()
  run("${PYTHON}" "${SOURCE_DIR}/tests/report/check_png.py" "${png}" 800)
  message(STATUS "${out}")
endforeach()
