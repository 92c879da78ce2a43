# KLU from SuiteSparse (Debian libsuitesparse-dev) -> KLU::KLU
include(SuiteSparseLibrary)
emb_find_suitesparse_library(KLU klu.h klu)
