# Writes OUT, a header holding the web page's template, style and script as
# raw string literals (the page is one file: they are inlined when exported).
file(READ ${DIR}/page.html html)
file(READ ${DIR}/page.css css)
file(READ ${DIR}/page.js js)
file(WRITE ${OUT}.tmp "#pragma once\n// Generated from report/web by embed.cmake.\nnamespace viewpipe::web {\n"
     "inline const char* kPageHtml = R\"VIEWPIPE(${html})VIEWPIPE\";\n"
     "inline const char* kPageCss = R\"VIEWPIPE(${css})VIEWPIPE\";\n"
     "inline const char* kPageJs = R\"VIEWPIPE(${js})VIEWPIPE\";\n}\n")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
