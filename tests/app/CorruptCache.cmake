# cmake -DDIR=<folder> -P CorruptCache.cmake: damages every cached reference image (*.pfm)
# in DIR, as a failing disk or an interrupted copy would (bytes appended), for the
# reference-cache tests. Fails when DIR holds no image (the test before stored none).
file(GLOB images "${DIR}/*.pfm")
if(NOT images)
  message(FATAL_ERROR "no cached reference in ${DIR}")
endif()
foreach(image ${images})
  file(APPEND "${image}" "damaged")
  message(STATUS "damaged ${image}")
endforeach()
