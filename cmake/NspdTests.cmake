# Test registration. Adding a test is adding a file:
#   tests/unit/<folder>/test_<topic>.c    -> ctest name unit.<folder>.<topic>, label "unit"
#                                            (the folder of src/ it tests: tests/unit/flow/gks/test_flux.c
#                                            is unit.flow.gks.flux)
#   tests/verify/<case>/test_<topic>.c    -> ctest name verify.<case>.<topic>, label "verify"
#   tests/cli/test_<topic>.sh             -> ctest name cli.<topic>, label "cli"
# A file whose first line contains "ctest-labels: a b" gets those labels too
# ("slow" keeps a test out of `make test`; `make validate` runs it); a C test
# whose second line contains "ctest-sources: x.c" is linked with x.c of its
# folder too (a translation unit compiled with other definitions, such as
# the unfused reference of a kernel).
pkg_check_modules(CMOCKA REQUIRED IMPORTED_TARGET cmocka)

file(GLOB NSPD_TEST_SUPPORT CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tests/support/*.c)
add_library(nspd_test_support STATIC ${NSPD_TEST_SUPPORT})
target_include_directories(nspd_test_support PUBLIC ${PROJECT_SOURCE_DIR}/tests/support)
target_link_libraries(nspd_test_support PUBLIC nspdlib PkgConfig::CMOCKA)
target_compile_definitions(nspd_test_support PUBLIC
    NSPD_SOURCE_DIR="${PROJECT_SOURCE_DIR}" NSPD_BINARY_DIR="${CMAKE_BINARY_DIR}")

function(nspd_extra_sources file out)
    file(STRINGS ${file} lines LIMIT_COUNT 2)
    set(sources "")
    foreach(line ${lines})
        if(line MATCHES "ctest-sources:([a-z0-9_. ]+)")
            string(STRIP "${CMAKE_MATCH_1}" l)
            string(REPLACE " " ";" names "${l}")
            get_filename_component(dir ${file} DIRECTORY)
            foreach(n ${names})
                list(APPEND sources ${dir}/${n})
            endforeach()
        endif()
    endforeach()
    set(${out} ${sources} PARENT_SCOPE)
endfunction()

function(nspd_extra_labels file out)
    file(STRINGS ${file} first LIMIT_COUNT 1)
    set(labels "")
    if(first MATCHES "ctest-labels:([a-z ]+)")
        string(STRIP "${CMAKE_MATCH_1}" l)
        string(REPLACE " " ";" labels "${l}")
    endif()
    set(${out} ${labels} PARENT_SCOPE)
endfunction()

# The sanitised build runs only the unit, cli and mpi tests (make
# test-asan); its verify executables (31, about 20 s of make test's
# builds) would never run, so it does not build them.
set(test_kinds unit verify)
if(NSPD_SANITIZE)
    set(test_kinds unit)
endif()
foreach(kind ${test_kinds})
    file(GLOB_RECURSE tests CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tests/${kind}/*/test_*.c)
    if(NSPD_EXCLUDE_TESTS_REGEX)
        list(FILTER tests EXCLUDE REGEX "${NSPD_EXCLUDE_TESTS_REGEX}")
    endif()
    foreach(src ${tests})
        get_filename_component(dir ${src} DIRECTORY)
        file(RELATIVE_PATH group ${PROJECT_SOURCE_DIR}/tests/${kind} ${dir})
        get_filename_component(stem ${src} NAME_WE)
        string(REGEX REPLACE "^test_" "" topic ${stem})
        string(REPLACE "/" "." name ${kind}.${group}.${topic})
        string(REPLACE "/" "_" exe ${kind}_${group}_${topic})
        nspd_extra_sources(${src} more)
        add_executable(${exe} ${src} ${more})
        target_link_libraries(${exe} PRIVATE nspd_test_support)
        add_test(NAME ${name} COMMAND ${exe} WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
        nspd_extra_labels(${src} extra)
        set_tests_properties(${name} PROPERTIES LABELS "${kind};${extra}"
            ENVIRONMENT "OMP_NUM_THREADS=2;OMP_WAIT_POLICY=passive")
    endforeach()
endforeach()

file(GLOB cli_tests CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tests/cli/test_*.sh)
foreach(script ${cli_tests})
    get_filename_component(stem ${script} NAME_WE)
    string(REGEX REPLACE "^test_" "" topic ${stem})
    add_test(NAME cli.${topic} COMMAND sh ${script} $<TARGET_FILE:nspd> ${PROJECT_SOURCE_DIR}
        WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
    nspd_extra_labels(${script} extra)
    set_tests_properties(cli.${topic} PROPERTIES LABELS "cli;${extra}" SKIP_RETURN_CODE 77
        ENVIRONMENT "OMP_NUM_THREADS=2;OMP_WAIT_POLICY=passive")
endforeach()
# The longest after mpi.run (60-85 s each in make test) start first: a fresh
# build has no timings, and in declaration order cli.resume began late and
# ran alone at the end of the release pass
set_tests_properties(cli.golden cli.resume cli.mutations PROPERTIES COST 300)
# ... and the sanitised pass's longest (12-25 s each there)
set_tests_properties(cli.bad_input cli.report cli.cases_check cli.run unit.flow.pddo.step
    unit.couple.penalty.gap unit.couple.penalty.coupling unit.flow.pddo.polar
    unit.flow.iga.solver PROPERTIES COST 100)

# The kernels (src/**/*_kernel.h) compiled as CUDA, compile only: no GPU is
# needed, only nvcc; without it the test reports itself skipped.
find_program(NSPD_NVCC nvcc)
if(NOT NSPD_NVCC)
    set(NSPD_NVCC "")
endif()
add_test(NAME unit.core.cuda_kernels
    COMMAND sh ${PROJECT_SOURCE_DIR}/tests/unit/core/cuda_kernels.sh "${NSPD_NVCC}"
        ${PROJECT_SOURCE_DIR} ${CMAKE_BINARY_DIR}/cuda_kernels
    WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
# "release": once, in the release build's run (nvcc compiles the headers
# itself; the sanitised build adds nothing but 10 s of make test)
set_tests_properties(unit.core.cuda_kernels PROPERTIES LABELS "unit;cuda;release" SKIP_RETURN_CODE 77)

# The marked loops (GKS rows, correspondence pairs) vectorised, as GCC
# reports it (tests/unit/core/vectorised.sh); skipped with another compiler.
# The release build writes the reports as it compiles (CMakeLists.txt,
# NSPD_VEC_REPORTS); elsewhere the script compiles the files itself.
if(NSPD_VEC_REPORTS)
    set(vec_source --from-build)
else()
    set(vec_source "")
endif()
add_test(NAME unit.core.vectorised
    COMMAND sh ${PROJECT_SOURCE_DIR}/tests/unit/core/vectorised.sh ${CMAKE_C_COMPILER}
        ${PROJECT_SOURCE_DIR} ${CMAKE_BINARY_DIR}/vectorised ${vec_source}
    WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
# "release": once, in the release build's run (it compiles the files
# itself, as the release build does; the sanitised build adds nothing)
set_tests_properties(unit.core.vectorised PROPERTIES LABELS "unit;release" SKIP_RETURN_CODE 77)

# The distributed engine (issue 28): tests/mpi/test_<topic>.c, each run by
# mpiexec on 1, 2, 3 and 4 ranks (ctest mpi.<topic>.ranks<N>, label "mpi"),
# oversubscribed on a machine with fewer cores, one OpenMP thread a rank.
# Open MPI refuses root unless told; CI runs as root.
if(NSPD_MPI)
    # bench/mpi_gks.c: the GKS step's strong and weak scaling (docs/PERFORMANCE.md)
    add_executable(bench_mpi_gks ${PROJECT_SOURCE_DIR}/bench/mpi_gks.c)
    target_link_libraries(bench_mpi_gks PRIVATE nspdlib)
    file(GLOB mpi_tests CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tests/mpi/test_*.c)
    foreach(src ${mpi_tests})
        get_filename_component(stem ${src} NAME_WE)
        string(REGEX REPLACE "^test_" "" topic ${stem})
        add_executable(mpi_${topic} ${src})
        target_link_libraries(mpi_${topic} PRIVATE nspd_test_support MPI::MPI_C)
        foreach(ranks 1 2 3 4)
            add_test(NAME mpi.${topic}.ranks${ranks}
                COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${ranks} --oversubscribe
                    $<TARGET_FILE:mpi_${topic}>
                WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
            set_tests_properties(mpi.${topic}.ranks${ranks} PROPERTIES LABELS "mpi"
                ENVIRONMENT "OMP_NUM_THREADS=1;OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_rmaps_base_oversubscribe=1;OMPI_MCA_mpi_yield_when_idle=1;OMPI_MCA_pml=ob1")
        endforeach()
    endforeach()
    # `mpirun nspd run`: flow cases bitwise on 1-4 ranks, checkpoints and
    # fields across process counts, the refusals (tests/mpi/run.sh)
    # tests/mpi/vtk_same.c: a grid written in pieces against the whole one
    add_executable(vtk_same ${PROJECT_SOURCE_DIR}/tests/mpi/vtk_same.c)
    target_link_libraries(vtk_same PRIVATE nspdlib)
    # make test's layouts of each case (mode suite), and the rest of them
    # in `make validate` (mode more, labelled slow; tests/mpi/run.sh)
    foreach(mode suite more)
        set(name mpi.run)
        if(mode STREQUAL more)
            set(name mpi.run_more)
        endif()
        add_test(NAME ${name}
            COMMAND sh ${PROJECT_SOURCE_DIR}/tests/mpi/run.sh $<TARGET_FILE:nspd>
                ${PROJECT_SOURCE_DIR} ${MPIEXEC_EXECUTABLE} $<TARGET_FILE:vtk_same> ${mode}
            WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
        # the longest test (about 1.3 minutes alone): run alone, first (a
        # fresh build has no timings yet); its up to 4 ranks beside another
        # test on 2 cores took 2.6 times as long (370 s in a fresh make test
        # on an AMD EPYC, with twice the layouts), more than the others gain
        # from running beside it
        set_tests_properties(${name} PROPERTIES LABELS "mpi;release" SKIP_RETURN_CODE 77
            COST 1000 RUN_SERIAL TRUE)
    endforeach()
    set_tests_properties(mpi.run_more PROPERTIES LABELS "mpi;release;slow")
    # the isogeometric flow and paper 003's system on 1-4 ranks, a coupled
    # resume 3 -> 2, the refusals (tests/mpi/iga.sh, issue 58); started
    # early (COST) so that it is not the suite's last, longest test
    add_test(NAME mpi.iga
        COMMAND sh ${PROJECT_SOURCE_DIR}/tests/mpi/iga.sh $<TARGET_FILE:nspd>
            ${PROJECT_SOURCE_DIR} ${MPIEXEC_EXECUTABLE} $<TARGET_FILE:vtk_same>
        WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
    set_tests_properties(mpi.iga PROPERTIES LABELS "mpi;release" COST 900)
    # the PDDO flow on 1-4 ranks, a resume 3 -> 2, the refusal (tests/mpi/
    # pddo.sh, issue 58)
    add_test(NAME mpi.pddo
        COMMAND sh ${PROJECT_SOURCE_DIR}/tests/mpi/pddo.sh $<TARGET_FILE:nspd>
            ${PROJECT_SOURCE_DIR} ${MPIEXEC_EXECUTABLE} $<TARGET_FILE:vtk_same>
        WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
    set_tests_properties(mpi.pddo PROPERTIES LABELS "mpi;release")
    # the sanitized build: a few of those cases under ASan and UBSan
    # (tests/mpi/sanitized.sh), in make test-asan's selection ("cli")
    if(NSPD_SANITIZE)
        add_test(NAME mpi.sanitized
            COMMAND sh ${PROJECT_SOURCE_DIR}/tests/mpi/sanitized.sh $<TARGET_FILE:nspd>
                ${PROJECT_SOURCE_DIR} ${MPIEXEC_EXECUTABLE} $<TARGET_FILE:vtk_same>
            WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
        set_tests_properties(mpi.sanitized PROPERTIES LABELS "mpi;cli" COST 500)
    endif()
endif()
