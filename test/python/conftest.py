"""Shared pytest rules for test/python: a skipped test must say why (pytest prints the reason
with -rs, as tools/test_all.sh runs it); a skip without a reason is reported as a failure."""
import pytest

import pecplas_py  # noqa: F401  (tools/ on the PYTHONPATH of the scripts the tests start)


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    report = outcome.get_result()
    if not report.skipped or getattr(report, "wasxfail", None) is not None:
        return
    reason = ""
    if isinstance(report.longrepr, tuple) and len(report.longrepr) == 3:
        reason = str(report.longrepr[2])
    reason = reason.removeprefix("Skipped:").strip()
    if reason in ("", "Skipped", "unconditional skip", "<Skipped instance>"):
        report.outcome = "failed"
        report.longrepr = f"{item.nodeid}: skipped without a reason; give pytest.skip(reason=...)"
