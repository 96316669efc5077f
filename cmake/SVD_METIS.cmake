# Defines the imported target SVD::METIS (METIS's header folder and library), from the cache
# variables SVD_METIS_INCLUDE_DIR and SVD_METIS_LIBRARY, found here when not set. Used by the
# package's build and by its installed config, so that the exported target holds no paths.
if(NOT TARGET SVD::METIS)
  find_path(SVD_METIS_INCLUDE_DIR metis.h)
  find_library(SVD_METIS_LIBRARY metis)
  if(SVD_METIS_INCLUDE_DIR AND SVD_METIS_LIBRARY)
    add_library(SVD::METIS UNKNOWN IMPORTED)
    set_target_properties(SVD::METIS PROPERTIES
      IMPORTED_LOCATION "${SVD_METIS_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${SVD_METIS_INCLUDE_DIR}")
  endif()
endif()
