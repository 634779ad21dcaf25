"""One run of one model: loading compiled models (built-in or built on demand), cam laws at
run time, the integration methods, the Simulator and its Result, the fixed-step stability
check, and the errors users see."""
