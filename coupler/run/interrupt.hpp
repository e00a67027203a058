// SIGINT/SIGTERM only raise a flag; the coupler checks it while waiting for participants
// and shuts down in order (participants stopped, file closed).
#pragma once

namespace cosim::run {

void install_interrupt_handlers();
bool interrupted();

}  // namespace cosim::run
