!!ARBfp1.0
# program.env[24]: beyond the minimum MAX_PROGRAM_ENV_PARAMETERS_ARB of 24 (ARBfp 3.11.3.2)
# no warning by default (Mesa takes it); --limits spec-min rejects it
MUL result.color, fragment.color, program.env[24];
END
