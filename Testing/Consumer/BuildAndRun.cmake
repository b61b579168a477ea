# Configure, build and run the consumer project against the PPIRay build tree,
# exactly as the README says: PPIRay_DIR only (the package finds its VTK).
file(REMOVE_RECURSE "${BINARY_DIR}")
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${BINARY_DIR}" -G "${GENERATOR}"
  "-DPPIRay_DIR=${PPIRAY_DIR}" RESULT_VARIABLE rc)
if (rc)
  message(FATAL_ERROR "configuring the consumer failed: find_package(PPIRay) is broken")
endif ()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BINARY_DIR}" RESULT_VARIABLE rc)
if (rc)
  message(FATAL_ERROR "building the consumer against PPIRay::Rendering failed")
endif ()
execute_process(COMMAND "${BINARY_DIR}/consumer" RESULT_VARIABLE rc)
if (rc)
  message(FATAL_ERROR "the consumer failed to run")
endif ()
