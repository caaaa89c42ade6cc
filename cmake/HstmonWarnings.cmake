# Strict warnings for project targets (never -ffast-math: the compensated
# summation in lib/ relies on IEEE evaluation order).
function(hstmon_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion
    -Wdouble-promotion -Wold-style-cast -Wnon-virtual-dtor -Wcast-align
    -Wnull-dereference -Wformat=2)
  if(HSTMON_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# Looser set for code that includes third-party headers with their own warnings.
function(hstmon_host_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wshadow)
  if(HSTMON_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
