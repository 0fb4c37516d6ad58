// Regression tests for the fuzzing findings of docs/robustness.md that still wait for their fix.
// Move into tests/robustness/ (and delete from here) once the fix is in; each test checks the
// correct behaviour, so it fails until then. Inputs are the ones the fuzzers saved
// (fuzz/findings/fuzz_<target>/), reduced to the call that goes wrong.
//
// This file is not compiled. No test waits here at the moment: R8's test moved to
// tests/robustness/fuzz_regression_test.cpp (OverflowingTriangleIsRejected) with its fix.
