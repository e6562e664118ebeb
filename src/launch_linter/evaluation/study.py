"""The study's own results, to print beside ours.

Table IV of the study ("Results (Using z threshold of 1.0)", in
``research/study-linting-roslaunch-static-transforms.txt``, section V.A): Launch-Linter run
on the 8,438 roslaunch files of repositories with fewer than 30 commits, with beliefs mined
from the others at p0 = 0.9. The figures are copied as published, including the total
faults (1,172), which is not the sum of the rows (1,130), and the total percentage (9.6%;
the text says 9.4%, 811 / 8,438 is 9.61%).
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class StudyRow:
    faults: int
    files: int
    percent: float
    """Percentage of the 8,438 files, as printed (two significant decimals)."""


STUDY_FILES = 8438
STUDY_MIN_Z = 1.0

STUDY_TABLE_IV: dict[str, StudyRow] = {
    "self_transform": StudyRow(4, 4, 0.05),
    "dup_name": StudyRow(50, 43, 0.51),
    "dup_sig": StudyRow(32, 28, 0.33),
    "reversed_name": StudyRow(211, 154, 1.8),
    "rot_degrees": StudyRow(5, 5, 0.06),
    "int_suffix": StudyRow(40, 25, 0.30),
    "ned_transform": StudyRow(3, 3, 0.04),
    "sensor_null": StudyRow(397, 354, 4.2),
    "sig_implication": StudyRow(24, 16, 0.19),
    "name_implication": StudyRow(100, 39, 0.46),
    "sig_null_disp": StudyRow(78, 76, 0.90),
    "name_null_disp": StudyRow(33, 31, 0.37),
    "sig_null_rot": StudyRow(88, 78, 0.92),
    "name_null_rot": StudyRow(65, 61, 0.72),
}
"""The study's 14 rows, in the study's order."""

STUDY_TOTAL = StudyRow(1172, 811, 9.6)
