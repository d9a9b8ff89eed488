# Writes OUT, a header holding the web page's template, style and script as
# raw string literals (the page is one file: they are inlined when exported).
# The script is in parts (DIR/page/): PARTS, a list of their names, joined in
# its order.
if(NOT PARTS)
  message(FATAL_ERROR "embed.cmake: PARTS, the script's parts in order, is empty")
endif()
file(READ ${DIR}/page.html html)
file(READ ${DIR}/page.css css)
set(js "")
foreach(part IN LISTS PARTS)
  file(READ ${DIR}/page/${part} text)
  string(APPEND js "${text}")
endforeach()
file(WRITE ${OUT}.tmp "#pragma once\n// Generated from report/web by embed.cmake.\nnamespace viewpipe::web {\n"
     "inline const char* kPageHtml = R\"VIEWPIPE(${html})VIEWPIPE\";\n"
     "inline const char* kPageCss = R\"VIEWPIPE(${css})VIEWPIPE\";\n"
     "inline const char* kPageJs = R\"VIEWPIPE(${js})VIEWPIPE\";\n}\n")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
