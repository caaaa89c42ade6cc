// A small hand-made signature table for the matcher tests, until the generated
// kThesisSignatures exists. Signs from the physics of the thesis rig (Table 2.2 point):
// magnitudes are steady-state deviations, slopes the sign at onset, orders the
// integrations on the fastest path (Pmi, Pmo are algebraic in ωm and the inputs).
// Directions: steady-state output change for a 0.1 % fault, divided by the sensor noise
// (0.05 bar, 0.5 rpm), normalised — computed once with ThesisReducedModel::steady_state.
#pragma once

#include "hstmon/fault_signature.hpp"

namespace hstmon_test {

using hstmon::FaultSignature;
constexpr std::int8_t P = hstmon::kQualPlus, M = hstmon::kQualMinus, Z = hstmon::kQualZero, A = hstmon::kQualAny;

// Channel order: Pmi, Pmo, Ppp, ωm. {magnitude, slope, order}
inline constexpr FaultSignature kTestTable[] = {
    {"kp-", false, {{P, P, 2}, {M, M, 2}, {P, P, 1}, {M, M, 2}}, {0.016932f, -0.016932f, 0.654057f, -0.756066f}},
    {"kp+", false, {{M, M, 2}, {P, P, 2}, {M, M, 1}, {P, P, 2}}, {-0.016942f, 0.016941f, -0.654162f, 0.755975f}},
    // Dp+: the pump delivers more at once (Ppp rises), the extra torque then slows the shaft
    // and Ppp settles lower.
    {"Dp+", false, {{P, P, 1}, {M, M, 1}, {M, P, 1}, {M, M, 1}}, {0.022334f, -0.022334f, -0.063853f, -0.997459f}},
    {"Rbl+", false, {{P, P, 1}, {M, M, 1}, {M, M, 2}, {M, M, 1}}, {0.010346f, -0.010346f, -0.886831f, -0.461862f}},
    {"Dm-", false, {{P, P, 0}, {M, M, 0}, {M, M, 2}, {M, M, 1}}, {0.036040f, -0.036040f, -0.885752f, -0.461352f}},
    {"kf-", false, {{M, M, 0}, {P, P, 0}, {M, M, 2}, {M, M, 1}}, {-0.070713f, 0.070713f, -0.882485f, -0.459587f}},
    {"Psupl-", false, {{M, M, 0}, {M, M, 1}, {M, M, 2}, {M, M, 1}}, {-0.150734f, -0.010228f, -0.876707f, -0.456684f}},
    {"sensor_p_mi", true, {{A, A, 0}, {Z, Z, 0}, {Z, Z, 0}, {Z, Z, 0}}, {0, 0, 0, 0}},
    {"sensor_p_mo", true, {{Z, Z, 0}, {A, A, 0}, {Z, Z, 0}, {Z, Z, 0}}, {0, 0, 0, 0}},
    {"sensor_p_pp", true, {{Z, Z, 0}, {Z, Z, 0}, {A, A, 0}, {Z, Z, 0}}, {0, 0, 0, 0}},
    {"sensor_w_m", true, {{Z, Z, 0}, {Z, Z, 0}, {Z, Z, 0}, {A, A, 0}}, {0, 0, 0, 0}},
};
inline constexpr int kTestTableCount = static_cast<int>(sizeof(kTestTable) / sizeof(kTestTable[0]));
static_assert(kTestTable[0].channel[2].magnitude == hstmon::kQualPlus, "the table is usable in constant expressions");

// Dp+, Rbl+, Dm− with one identical qualitative signature (Ppp slope not predicted): only
// the direction tells them apart.
inline constexpr FaultSignature kTieTable[] = {
    {"Dp+", false, {{P, P, 1}, {M, M, 1}, {M, A, 1}, {M, M, 1}}, {0.022334f, -0.022334f, -0.063853f, -0.997459f}},
    {"Rbl+", false, {{P, P, 1}, {M, M, 1}, {M, A, 1}, {M, M, 1}}, {0.010346f, -0.010346f, -0.886831f, -0.461862f}},
    {"Dm-", false, {{P, P, 1}, {M, M, 1}, {M, A, 1}, {M, M, 1}}, {0.036040f, -0.036040f, -0.885752f, -0.461352f}},
};

}  // namespace hstmon_test
