/* piglit fbo/fbo-alphatest-formats boundaries on an 8x1 window, one pixel per case (alpha,
   function, reference): 0.2 LESS 0.25 pass; 0.96 LEQUAL 0.92 fail; 0.6 GREATER 0.55 pass; 0.9
   GREATER 0.1 pass; 0.35 GEQUAL 0.4 fail; 0.4 EQUAL 0.4 pass; 0.8 NOTEQUAL 0.8 fail; NEVER
   fail. A passing pixel is white with its alpha, a failing one keeps the clear colour (0, 0,
   0, 0). */
glClearColor(0, 0, 0, 0);
glClear(GL_COLOR_BUFFER_BIT);
glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glOrtho(0, 8, 0, 1, -1, 1);
glMatrixMode(GL_MODELVIEW);
glLoadIdentity();
glEnable(GL_ALPHA_TEST);
glAlphaFunc(GL_LESS, 0.25f);
glColor4f(1, 1, 1, 0.2f);
glBegin(GL_QUADS);
glVertex3f(0, 0, 0); glVertex3f(1, 0, 0); glVertex3f(1, 1, 0); glVertex3f(0, 1, 0);
glEnd();
glAlphaFunc(GL_LEQUAL, 0.92f);
glColor4f(1, 1, 1, 0.96f);
glBegin(GL_QUADS);
glVertex3f(1, 0, 0); glVertex3f(2, 0, 0); glVertex3f(2, 1, 0); glVertex3f(1, 1, 0);
glEnd();
glAlphaFunc(GL_GREATER, 0.55f);
glColor4f(1, 1, 1, 0.6f);
glBegin(GL_QUADS);
glVertex3f(2, 0, 0); glVertex3f(3, 0, 0); glVertex3f(3, 1, 0); glVertex3f(2, 1, 0);
glEnd();
glAlphaFunc(GL_GREATER, 0.1f);
glColor4f(1, 1, 1, 0.9f);
glBegin(GL_QUADS);
glVertex3f(3, 0, 0); glVertex3f(4, 0, 0); glVertex3f(4, 1, 0); glVertex3f(3, 1, 0);
glEnd();
glAlphaFunc(GL_GEQUAL, 0.4f);
glColor4f(1, 1, 1, 0.35f);
glBegin(GL_QUADS);
glVertex3f(4, 0, 0); glVertex3f(5, 0, 0); glVertex3f(5, 1, 0); glVertex3f(4, 1, 0);
glEnd();
glAlphaFunc(GL_EQUAL, 0.4f);
glColor4f(1, 1, 1, 0.4f);
glBegin(GL_QUADS);
glVertex3f(5, 0, 0); glVertex3f(6, 0, 0); glVertex3f(6, 1, 0); glVertex3f(5, 1, 0);
glEnd();
glAlphaFunc(GL_NOTEQUAL, 0.8f);
glColor4f(1, 1, 1, 0.8f);
glBegin(GL_QUADS);
glVertex3f(6, 0, 0); glVertex3f(7, 0, 0); glVertex3f(7, 1, 0); glVertex3f(6, 1, 0);
glEnd();
glAlphaFunc(GL_NEVER, 3f);
glColor4f(1, 1, 1, 0.5f);
glBegin(GL_QUADS);
glVertex3f(7, 0, 0); glVertex3f(8, 0, 0); glVertex3f(8, 1, 0); glVertex3f(7, 1, 0);
glEnd();
