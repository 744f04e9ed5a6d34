"""netft_utils services (ssc_twin.sil): the types exist; the lab's scripts tare in Python."""

from ssc_twin.sil.messages import service as _s

SetBias, SetBiasRequest, SetBiasResponse = _s(
    "netft_utils/SetBias",
    [("toBias", False), ("forceMax", 0.0), ("torqueMax", 0.0)],
    [("success", False)],
)
SetMax, SetMaxRequest, SetMaxResponse = _s(
    "netft_utils/SetMax", [("forceMax", 0.0), ("torqueMax", 0.0)], [("success", False)]
)
SetThreshold, SetThresholdRequest, SetThresholdResponse = _s(
    "netft_utils/SetThreshold", [("data", None)], [("success", False)]
)
SetToolData, SetToolDataRequest, SetToolDataResponse = _s(
    "netft_utils/SetToolData", [("mass", 0.0), ("COM", 0.0)], [("success", False)]
)
SetFilter, SetFilterRequest, SetFilterResponse = _s(
    "netft_utils/SetFilter",
    [("toFilter", False), ("deltaT", 0.0), ("cutoffFrequency", 0.0)],
    [("success", False)],
)
GetDouble, GetDoubleRequest, GetDoubleResponse = _s("netft_utils/GetDouble", [], [("weight", 0.0)])
StartSim, StartSimRequest, StartSimResponse = _s(
    "netft_utils/StartSim",
    [("simDim", 0), ("simType", 0), ("simSlope", 0.0), ("maxSimVal", 0.0)],
    [],
)
StopSim, StopSimRequest, StopSimResponse = _s("netft_utils/StopSim", [], [])
