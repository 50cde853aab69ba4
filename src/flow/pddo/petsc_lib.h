/* PETSc opened on the first PETSc pressure solve (core/shared_lib.h says
 * why; PETSc pulls in MUMPS, hypre, ScaLAPACK and some 60 more libraries).
 * Included by flow/pddo/ppe_petsc.c only, and only where CMake found PETSc
 * (NSPD_HAVE_PETSC): each name below, used as a call, goes through the
 * slot shared_lib_load filled; petsc_lib_load() must succeed before. */
#ifndef NSPD_FLOW_PDDO_PETSC_LIB_H
#define NSPD_FLOW_PDDO_PETSC_LIB_H

#ifdef NSPD_HAVE_PETSC
#include <petscksp.h>

/* every function flow/pddo/ppe_petsc.c calls */
#define PETSC_LIB_FUNCTIONS(X)                                                                     \
    X(KSPCreate)                                                                                   \
    X(KSPDestroy)                                                                                  \
    X(KSPGetConvergedReason)                                                                       \
    X(KSPGetIterationNumber)                                                                       \
    X(KSPGetPC)                                                                                    \
    X(KSPGetResidualNorm)                                                                          \
    X(KSPSetFromOptions)                                                                           \
    X(KSPSetInitialGuessNonzero)                                                                   \
    X(KSPSetNormType)                                                                              \
    X(KSPSetOperators)                                                                             \
    X(KSPSetOptionsPrefix)                                                                         \
    X(KSPSetPCSide)                                                                                \
    X(KSPSetTolerances)                                                                            \
    X(KSPSetType)                                                                                  \
    X(KSPSetUp)                                                                                    \
    X(KSPSolve)                                                                                    \
    X(MatCreateMPIAIJWithArrays)                                                                   \
    X(MatDestroy)                                                                                  \
    X(MatMumpsGetInfog)                                                                            \
    X(MatMumpsSetIcntl)                                                                            \
    X(MatTranspose)                                                                                \
    X(PCFactorGetMatrix)                                                                           \
    X(PCFactorSetMatSolverType)                                                                    \
    X(PCFactorSetUpMatSolverType)                                                                  \
    X(PCHYPRESetType)                                                                              \
    X(PCSetType)                                                                                   \
    X(PetscFinalize)                                                                               \
    X(PetscInitialize)                                                                             \
    X(PetscInitialized)                                                                            \
    X(PetscOptionsHasName)                                                                         \
    X(PetscOptionsSetValue)                                                                        \
    X(PetscPushErrorHandler)                                                                       \
    X(PetscReturnErrorHandler)                                                                     \
    X(VecCreateMPIWithArray)                                                                       \
    X(VecDestroy)                                                                                  \
    X(VecPlaceArray)                                                                               \
    X(VecResetArray)

enum {
#define PETSC_LIB_INDEX(f) PETSC_LIB_##f,
    PETSC_LIB_FUNCTIONS(PETSC_LIB_INDEX) PETSC_LIB_COUNT
#undef PETSC_LIB_INDEX
};

extern void *petsc_lib_slots[PETSC_LIB_COUNT];

/* Opens PETSc on the first call; NSPD_ERR_IO (with what is missing) if it cannot. */
int petsc_lib_load(void);

/* f's slot as a pointer to f's own type */
#define PETSC_LIB_CALL(f)          ((__typeof__(f) *)petsc_lib_slots[PETSC_LIB_##f])
#define KSPCreate                  PETSC_LIB_CALL(KSPCreate)
#define KSPDestroy                 PETSC_LIB_CALL(KSPDestroy)
#define KSPGetConvergedReason      PETSC_LIB_CALL(KSPGetConvergedReason)
#define KSPGetIterationNumber      PETSC_LIB_CALL(KSPGetIterationNumber)
#define KSPGetPC                   PETSC_LIB_CALL(KSPGetPC)
#define KSPGetResidualNorm         PETSC_LIB_CALL(KSPGetResidualNorm)
#define KSPSetFromOptions          PETSC_LIB_CALL(KSPSetFromOptions)
#define KSPSetInitialGuessNonzero  PETSC_LIB_CALL(KSPSetInitialGuessNonzero)
#define KSPSetNormType             PETSC_LIB_CALL(KSPSetNormType)
#define KSPSetOperators            PETSC_LIB_CALL(KSPSetOperators)
#define KSPSetOptionsPrefix        PETSC_LIB_CALL(KSPSetOptionsPrefix)
#define KSPSetPCSide               PETSC_LIB_CALL(KSPSetPCSide)
#define KSPSetTolerances           PETSC_LIB_CALL(KSPSetTolerances)
#define KSPSetType                 PETSC_LIB_CALL(KSPSetType)
#define KSPSetUp                   PETSC_LIB_CALL(KSPSetUp)
#define KSPSolve                   PETSC_LIB_CALL(KSPSolve)
#define MatCreateMPIAIJWithArrays  PETSC_LIB_CALL(MatCreateMPIAIJWithArrays)
#define MatDestroy                 PETSC_LIB_CALL(MatDestroy)
#define MatMumpsGetInfog           PETSC_LIB_CALL(MatMumpsGetInfog)
#define MatMumpsSetIcntl           PETSC_LIB_CALL(MatMumpsSetIcntl)
#define MatTranspose               PETSC_LIB_CALL(MatTranspose)
#define PCFactorGetMatrix          PETSC_LIB_CALL(PCFactorGetMatrix)
#define PCFactorSetMatSolverType   PETSC_LIB_CALL(PCFactorSetMatSolverType)
#define PCFactorSetUpMatSolverType PETSC_LIB_CALL(PCFactorSetUpMatSolverType)
#define PCHYPRESetType             PETSC_LIB_CALL(PCHYPRESetType)
#define PCSetType                  PETSC_LIB_CALL(PCSetType)
#define PetscFinalize              PETSC_LIB_CALL(PetscFinalize)
#define PetscInitialize            PETSC_LIB_CALL(PetscInitialize)
#define PetscInitialized           PETSC_LIB_CALL(PetscInitialized)
#define PetscOptionsHasName        PETSC_LIB_CALL(PetscOptionsHasName)
#define PetscOptionsSetValue       PETSC_LIB_CALL(PetscOptionsSetValue)
#define PetscPushErrorHandler      PETSC_LIB_CALL(PetscPushErrorHandler)
#define PetscReturnErrorHandler    PETSC_LIB_CALL(PetscReturnErrorHandler)
#define VecCreateMPIWithArray      PETSC_LIB_CALL(VecCreateMPIWithArray)
#define VecDestroy                 PETSC_LIB_CALL(VecDestroy)
#define VecPlaceArray              PETSC_LIB_CALL(VecPlaceArray)
#define VecResetArray              PETSC_LIB_CALL(VecResetArray)

#endif /* NSPD_HAVE_PETSC */
#endif
