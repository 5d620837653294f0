# Run by ctest after the tests gtest_discover_tests found (TEST_INCLUDE_FILES,
# ../CMakeLists.txt): the slowest tests get as COST about the seconds they take
# under ctest -j2 on 2 cores. ctest starts tests in decreasing cost; from its
# second run in a build directory it uses the times it measured, but on the
# first (a fresh clone) all costs are equal and a slow test that happens to
# start late ends the run alone. Only the order matters: a test renamed or
# faster leaves a stale entry harmless.
set(unfold_test_costs
  "^RobustSharedDataCats\\." 10
  "^BackendVolume\\.NoInvertedTetrahedraOnWolf0$" 10
  "^RobustTetrahedralize\\.AutoOnLargeSurfaces" 5
  "^ClosedMouth\\.(LipsTouch|SurfacesAreValid)" 4
  "^PipelinePose\\.(Default|ContactConfig|Invariant|ACoarse)" 4
  "^Shapes/StoredRestSurfaces\\." 3
  "^(LumpedStretch\\.TheCanonicalForm|Batch\\.AShardSplit|SparseCholesky\\.LargeSolves)" 3
  "^(BackendCompare\\.FixedBetaEnergiesAgreeOnWolf0|CompareMatrix\\.|BatchMatrix\\.Every)" 3
  "RobustSharedData\\." 2)
foreach(test IN LISTS unfold_tests_TESTS)
  set(costs ${unfold_test_costs})
  while(costs)
    list(POP_FRONT costs pattern seconds)
    if(test MATCHES "${pattern}")
      set_tests_properties("${test}" PROPERTIES COST ${seconds})
      break()
    endif()
  endwhile()
endforeach()
