"""Diagnosis: why the engines see different robots in one file, computed once for the API, the CLI and pytest.

``diagnose(model, ...)`` (:mod:`~koenig_check.diagnosis.diagnose`) is the one entry point; it reads the import
parity (:mod:`~koenig_check.diagnosis.import_parity`), the optional engines per the checker's policy
(:mod:`~koenig_check.diagnosis.policy`) and the three-engine verdicts (:mod:`~koenig_check.diagnosis.three_way`);
:mod:`~koenig_check.diagnosis.reason` turns the findings into the one-line reason.
"""
