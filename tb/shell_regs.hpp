// SPDX-License-Identifier: MIT
// The register map of the APB shell (rtl/acore_apb.v, README "Register shell (APB)"): byte
// addresses and bit fields, for the driver (tb/shell_driver.*) and the tests.
#pragma once
#include <cstdint>

namespace acore::shell {

constexpr uint32_t kId = 0x000;  // RO 0x4143_0100
constexpr uint32_t kConfig0 =
    0x004;  // RO DEGREE, REGIONS, CORRECTION, XCENTER, ZERO, SERIAL, FOLD, K
constexpr uint32_t kConfig1 = 0x008;      // RO WORDS, FOURIER_K, REG_W
constexpr uint32_t kConfig2 = 0x00C;      // RO LATENCY, CYCLES
constexpr uint32_t kConfig3 = 0x010;      // RO IN_W, ANGLE_W, MAG_W, CRC_W
constexpr uint32_t kCtrl = 0x020;         // RW
constexpr uint32_t kStatus = 0x024;       // W1C sticky [5:0], RO live [18:16]
constexpr uint32_t kIrq = 0x028;          // RO STATUS[5:0] & IRQ_EN
constexpr uint32_t kMagLo = 0x030;        // RW
constexpr uint32_t kMagHi = 0x034;        // RW
constexpr uint32_t kCrcExpected = 0x040;  // RW
constexpr uint32_t kCrcShadow = 0x044;    // RO
constexpr uint32_t kCrcRef = 0x048;       // RO
constexpr uint32_t kCrcScrub = 0x04C;     // RO
constexpr uint32_t kScrubPasses = 0x050;  // RO
constexpr uint32_t kWindow = 0x400;       // RW shadow word a at kWindow + 4 a
constexpr uint32_t kAddrSpace = 0x1000;   // APB_AW = 12

constexpr uint32_t kIdValue = 0x41430100;

// CTRL
constexpr uint32_t kCtrlCommit = 1u << 0;
constexpr uint32_t kCtrlClear = 1u << 1;
constexpr uint32_t kCtrlCrcCheck = 1u << 2;
constexpr uint32_t kCtrlScrub = 1u << 3;
constexpr int kCtrlIrqEnShift = 8;

// STATUS (sticky bits; IRQ_EN and IRQ use the same positions)
constexpr uint32_t kStOvf = 1u << 0;
constexpr uint32_t kStLos = 1u << 1;
constexpr uint32_t kStDos = 1u << 2;
constexpr uint32_t kStCrcShadow = 1u << 3;
constexpr uint32_t kStCrcActive = 1u << 4;
constexpr uint32_t kStDone = 1u << 5;
constexpr uint32_t kStSticky = 0x3f;
constexpr uint32_t kStBusy = 1u << 16;
constexpr uint32_t kStBank = 1u << 17;
constexpr uint32_t kStRefValid = 1u << 18;

}  // namespace acore::shell
