// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.1 "White space: the space character, horizontal tab, vertical tab, form feed, carriage-return, and line-feed."
#version 110
void	main ( )
{
	 gl_Position	=	vec4( 0.0 );	
}
