# HYLIOS_SANITIZE=ON builds everything with ASan + UBSan (errors abort, so CTest sees them).
if(HYLIOS_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
