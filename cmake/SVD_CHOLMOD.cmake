# Defines the imported target SVD::CHOLMOD (SuiteSparse's CHOLMOD: the folder of cholmod.h and
# the library), from the cache variables SVD_CHOLMOD_INCLUDE_DIR and SVD_CHOLMOD_LIBRARY, found
# here when not set. Eigen's CholmodSupport includes <cholmod.h>, which Debian puts in
# /usr/include/suitesparse. The library is not a dependency of the package's target: the
# programs that plug CHOLMOD into the embedding link this target themselves.
if(NOT TARGET SVD::CHOLMOD)
  find_path(SVD_CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
  find_library(SVD_CHOLMOD_LIBRARY cholmod)
  if(SVD_CHOLMOD_INCLUDE_DIR AND SVD_CHOLMOD_LIBRARY)
    add_library(SVD::CHOLMOD UNKNOWN IMPORTED)
    set_target_properties(SVD::CHOLMOD PROPERTIES
      IMPORTED_LOCATION "${SVD_CHOLMOD_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${SVD_CHOLMOD_INCLUDE_DIR}")
  endif()
endif()
