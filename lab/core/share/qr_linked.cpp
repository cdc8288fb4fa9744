// qr_linked.cpp — libqrencode linked in (qr_encoder.h): the desktop and the command line.
#include "core/share/qr_encoder.h"
#include "core/share/qr_symbol.h"

namespace lab {

ModuleState qrEncoderState() { return ModuleState::Ready; }
std::string qrEncoderProblem() { return {}; }
void loadQrEncoder() {}
std::optional<QrCode> runQrEncoder(std::string_view text, std::string& error) { return qrSymbol(text, error); }

} // namespace lab
