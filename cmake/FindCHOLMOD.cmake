# CHOLMOD from SuiteSparse (Debian libsuitesparse-dev) -> CHOLMOD::CHOLMOD
include(SuiteSparseLibrary)
emb_find_suitesparse_library(CHOLMOD cholmod.h cholmod)
