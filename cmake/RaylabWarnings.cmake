# Warning flags for RayLab's own targets: call raylab_set_warnings(target).
function(raylab_set_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall              # the common mistakes
    -Wextra            # unused parameters, sign mix-ups in comparisons
    -Wpedantic         # non-standard extensions we would not notice otherwise
    -Wshadow           # a local hiding a member is a classic geometry bug (t vs m_t)
    -Wnon-virtual-dtor # shapes are deleted through Shape*
    -Wno-unused-parameter  # interface implementations often ignore an argument
  )
  if(RAYLAB_STRICT_BUILD)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
