// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "Each number sign (#) can be preceded in its line only by spaces or horizontal tabs." "It may also be followed by spaces and horizontal tabs, preceding the directive."
#version 110
  	#  	define SCALE 2.0
	 	#ifdef SCALE
void main()
{
    gl_Position = vec4(SCALE);
}
  #  endif
