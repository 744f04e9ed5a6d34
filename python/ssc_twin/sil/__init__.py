"""Software in the loop: the lab's ROS 1 + ur_rtde scripts drive the twin, unchanged.

    python -m ssc_twin.sil SCRIPT [ARGS...]        # or: ssc sil SCRIPT [ARGS...]

``standins/`` holds rospy, tf, rtde_control, rtde_receive and the message and service packages
the lab's scripts import; ``world`` is the simulated cell behind them; ``noop`` serves plots,
cameras and learned models as harmless no-ops; ``runner`` runs a script (docs/sil.md).
"""

import os as _os

STANDINS = _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), "standins")


def save_data_params(args, append_txt="", mat_dir=None, recording=None):
    """The lab's merged DataLog_<stamp>_<append_txt>.mat from the logger's latest recording,
    written by the C++ MAT writer (robotlog/mat_log.h). `args`: a dict or argparse Namespace of
    the script's arguments (Pref, beta, d_lat, diskRadius, start_offset, P_lims, alpha_beta,
    success, Fz_set, edgeFollowing_history rows [t, x, y, r_p, corr_p, r_p_final, F, P1..P4]).
    Returns the path."""
    import numpy as np
    from .. import _core
    from .current import current

    w = current()
    if recording is None:
        if not w.logger.paths:
            raise RuntimeError("save_data_params: the data logger has recorded nothing")
        recording = _os.path.join(w.tmp_dir, _os.path.basename(w.logger.paths[0]))
    d = dict(vars(args)) if not isinstance(args, dict) else dict(args)
    if "edgeFollowing_history" in d:
        d["edgeFollowing_history"] = [
            [float(v) for v in np.concatenate([np.ravel(np.asarray(x, dtype=float)) for x in row])]
            for row in d["edgeFollowing_history"]
        ]
    keep = {}
    for k, v in d.items():
        if k == "edgeFollowing_history":
            keep[k] = v
        elif isinstance(v, (int, float)) and not isinstance(v, bool):
            keep[k] = float(v)
        elif isinstance(v, (list, tuple, np.ndarray)):
            try:
                keep[k] = [float(x) for x in np.ravel(np.asarray(v, dtype=float))]
            except (TypeError, ValueError):
                pass
    if mat_dir is None:
        from datetime import datetime

        mat_dir = _os.path.join(
            _os.path.expanduser("~"), "SuctionExperiment", datetime.now().strftime("%y%m%d")
        )
    _os.makedirs(mat_dir, exist_ok=True)
    return _core.write_lab_mat(recording, mat_dir, append_txt, keep)
