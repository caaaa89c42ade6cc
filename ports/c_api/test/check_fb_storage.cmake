# c_api.fb_storage: the IEC 61131-3 wrapper's Storage array (hstmon_fb.st, 32-bit runtime)
# holds HSTMON_MONITOR_STORAGE_BYTES of hstmon_c.h's 32-bit branch for the default library.
# A PLC compiler does not see the C header, so nothing else would notice the two drift apart
# (hstmon_create then refuses the short buffer at run time).
# Usage: cmake -DHEADER=hstmon_c.h -DFB=hstmon_fb.st -P check_fb_storage.cmake
file(READ "${HEADER}" header)
file(READ "${FB}" fb)
# The default library's 32-bit size: the branch after `#elif UINTPTR_MAX > …` (64-bit).
string(REGEX MATCH "#elif UINTPTR_MAX > 0xFFFFFFFFu\n#define HSTMON_MONITOR_STORAGE_BYTES [0-9]+u\n#else\n#define HSTMON_MONITOR_STORAGE_BYTES ([0-9]+)u"
       found "${header}")
if(NOT found)
  message(FATAL_ERROR "${HEADER}: no 32-bit HSTMON_MONITOR_STORAGE_BYTES for the default library")
endif()
set(bytes ${CMAKE_MATCH_1})
string(REGEX MATCH "Storage *: *ARRAY\\[0\\.\\.([0-9]+)\\] OF BYTE" found "${fb}")
if(NOT found)
  message(FATAL_ERROR "${FB}: no `Storage : ARRAY[0..N] OF BYTE`")
endif()
math(EXPR fb_bytes "${CMAKE_MATCH_1} + 1")
if(NOT fb_bytes EQUAL bytes)
  message(FATAL_ERROR "${FB}: Storage holds ${fb_bytes} B, hstmon_c.h reserves ${bytes} B on 32-bit targets")
endif()
message(STATUS "hstmon_fb.st Storage: ${fb_bytes} B = HSTMON_MONITOR_STORAGE_BYTES (32-bit)")
