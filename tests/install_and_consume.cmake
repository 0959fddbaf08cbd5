# ctest install_and_consume (cmake/install.cmake): `cmake --install` of the existing build tree
# into PREFIX (nothing is rebuilt), then what a user of the installed hbtrack does:
#   1. configures and builds examples/consumer with find_package(hbtrack) and runs it on Duffing;
#   2. runs PREFIX/bin/hbtrack;
#   3. imports the installed Python package with matplotlib made unimportable, then computes;
#   4. copies the tool and the Python package to another prefix and draws a figure there with
#      `hbtrack plot`, in an environment that names neither the source nor the build tree.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "failed (${code}): ${ARGN}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${PREFIX})
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX})
foreach(installed bin/hbtrack include/hbtrack/analysis/nfrc.hpp)
  if(NOT EXISTS ${PREFIX}/${installed})
    message(FATAL_ERROR "not installed: ${PREFIX}/${installed}")
  endif()
endforeach()

set(consumer_build ${PREFIX}/consumer-build)
set(launcher "")
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/consumer -B ${consumer_build} -G "${GENERATOR}"
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX_COMPILER} ${launcher} -DCMAKE_PREFIX_PATH=${PREFIX})
run(${CMAKE_COMMAND} --build ${consumer_build})
run(${consumer_build}/nfrc_peak ${SOURCE_DIR}/examples/duffing.toml)
message(STATUS "consumer: ${last_output}")
# Duffing (examples/duffing.toml) folds: the consumer must have found its two limit points.
if(NOT last_output MATCHES "limit_points 2 stop reached_end")
  message(FATAL_ERROR "consumer output unexpected: ${last_output}")
endif()

run(${PREFIX}/bin/hbtrack --help)
if(NOT last_output MATCHES "frc")
  message(FATAL_ERROR "installed hbtrack --help does not list frc: ${last_output}")
endif()

if(PYTHON AND NOT IS_ABSOLUTE "${PYTHON_DIR}")
  # Only the installed prefix on the path (-I ignores PYTHONPATH and the user's site-packages).
  set(script [=[
import sys
sys.path.insert(0, sys.argv[1])
sys.modules["matplotlib"] = None  # any `import matplotlib` now raises ImportError
import hbtrack
assert hbtrack.__file__.startswith(sys.argv[1]), hbtrack.__file__
case = hbtrack.load_case(sys.argv[2])
result = hbtrack.frc(case)
lps = [p for p in result["special_points"] if p["type"] == "LP"]
assert len(lps) == 2, lps
try:
    hbtrack.plots
except ImportError:
    print("plots need matplotlib: ok")
else:
    raise AssertionError("hbtrack.plots imported without matplotlib")
print("python: ok", len(result["branch"]["omega"]), "points")
]=])
  run(${PYTHON} -I -c "${script}" ${PREFIX}/${PYTHON_DIR} ${SOURCE_DIR}/examples/duffing.toml)
  message(STATUS "${last_output}")
endif()

if(PYTHON AND NOT IS_ABSOLUTE "${PYTHON_DIR}")
  # The tool finds the package relative to itself (apps/hbtrack/python_package.cpp): a copied
  # prefix draws with its own copy. Python caches the bytecode of what it imports beside it, so
  # the copy's __pycache__ shows which package drew.
  set(moved ${PREFIX}-moved)
  file(REMOVE_RECURSE ${moved})
  file(COPY ${PREFIX}/bin DESTINATION ${moved})
  get_filename_component(package_parent ${moved}/${PYTHON_DIR} ABSOLUTE)
  file(COPY ${PREFIX}/${PYTHON_DIR}/hbtrack DESTINATION ${package_parent} PATTERN "__pycache__" EXCLUDE)
  set(clean_env ${CMAKE_COMMAND} -E env --unset=PYTHONPATH --unset=HBTRACK_PYTHON --unset=PYTHONDONTWRITEBYTECODE
                --unset=PYTHONPYCACHEPREFIX --unset=PYTHONHOME MPLBACKEND=Agg)
  run(${CMAKE_COMMAND} -E chdir ${moved} ${clean_env} ${moved}/bin/hbtrack frc ${SOURCE_DIR}/examples/duffing.toml -q -o ${moved}/duffing)
  run(${CMAKE_COMMAND} -E chdir ${moved} ${clean_env} ${moved}/bin/hbtrack plot ${moved}/duffing -o ${moved}/figures)
  if(NOT EXISTS ${moved}/figures/nfrc.png OR NOT last_output MATCHES "nfrc.png")
    message(FATAL_ERROR "the moved prefix's hbtrack plot drew no nfrc.png: ${last_output}")
  endif()
  file(GLOB compiled ${package_parent}/hbtrack/__pycache__/plot.*.pyc)
  if(NOT compiled)
    message(FATAL_ERROR "hbtrack plot of ${moved} did not import the package copied beside it (${package_parent}/hbtrack)")
  endif()
  message(STATUS "moved prefix: hbtrack plot drew with ${package_parent}/hbtrack")
  file(REMOVE_RECURSE ${moved})
endif()
