from __future__ import annotations

from setuptools import find_packages, setup

package_name = "ament_launch_linter"

setup(
    name=package_name,
    version="0.1.0",
    packages=find_packages(exclude=["test"]),
    data_files=[
        ("share/ament_index/resource_index/packages", [f"resource/{package_name}"]),
        (f"share/{package_name}", ["package.xml"]),
    ],
    install_requires=["setuptools"],
    zip_safe=True,
    description="Launch-Linter as an ament linter (xUnit results for colcon test).",
    license="BSD-3-Clause",
    entry_points={
        "console_scripts": [f"ament_launch_linter = {package_name}.main:main"],
        "pytest11": [f"ament_launch_linter = {package_name}.pytest_marker"],
    },
)
