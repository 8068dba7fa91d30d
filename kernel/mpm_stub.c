int mpm_stub_unused(void); int mpm_stub_unused(void) { return 0; }
