"""The amplifier study at smoke size: every section written, figures real."""
import os
import subprocess
import sys

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def test_amplifier_study_smoke(tmp_path):
    out = tmp_path / "amplifier"
    p = subprocess.run([sys.executable, "-m", "shockfem", "study", "amplifier", "--size", "smoke", "--out", str(out)],
                       capture_output=True, text=True, timeout=900)
    assert p.returncode == 0, p.stderr
    report = (out / "report.md").read_text()
    for section in ("## 1. The white paper's sizing claim", "## 2. Apparent restitution",
                    "## 3. The five-mass design"):
        assert section in report
    # the closed forms: 775 lb of intermediate masses at 325 ft/s, e = 0.9 (launched chain)
    assert "| launched-chain | 0.9 | 325 | 2082 | 775 |" in report
    assert (out / "restitution_vs_frequency_ratio.png").stat().st_size > 20_000
    assert "| axisymmetric (30 mm) |" in report
