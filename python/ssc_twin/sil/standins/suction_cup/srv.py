"""The lab's suction_cup services (srv/Enable.srv, srv/PCB_location.srv)."""

from ssc_twin.sil.messages import service as _s

Enable, EnableRequest, EnableResponse = _s(
    "suction_cup/Enable", [("EnableDataLogging", False)], [("OutputFileName", "")]
)
PCB_location, PCB_locationRequest, PCB_locationResponse = _s(
    "suction_cup/PCB_location", [("Start", False)], [("x", 0), ("y", 0), ("theta", 0.0)]
)
