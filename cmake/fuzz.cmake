# libFuzzer targets (clang, ASan + UBSan).
