"""``tarsim bench``: each method's error against the analytic solver and a 50-digit mpmath
reference, error against run time as SVG plots, the stiff and extreme suite, and every
other chapter's rows and extremes (gear trains, cams, force polygons, balancing, the
flywheel) against closed forms.

It runs from a source checkout only (it is not installed with tarsim): the command line
finds this folder from the package's own place. See :func:`.report.write_report`.
"""

from .report import write_report

__all__ = ["write_report"]
