/* jello-grader-gl-functions-5.h: the GL, GLU and GLUT functions of the grader's GL stand-in
   (jello-grader-gl.h), a part of at most 60000 bytes: each file built into the
   grader stays a string under 64 kB. Made by scripts/make-gl-standins. */
typedef JELLO_GRADER_PROC(PFNGLTEXTURESTORAGE2DEXTPROC);
#define glTextureStorage2DMultisample(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESTORAGE2DMULTISAMPLEPROC);
#define glTextureStorage2DMultisampleEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESTORAGE2DMULTISAMPLEEXTPROC);
#define glTextureStorage3D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESTORAGE3DPROC);
#define glTextureStorage3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESTORAGE3DEXTPROC);
#define glTextureStorage3DMultisample(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESTORAGE3DMULTISAMPLEPROC);
#define glTextureStorage3DMultisampleEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESTORAGE3DMULTISAMPLEEXTPROC);
#define glTextureStorageMem1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESTORAGEMEM1DEXTPROC);
#define glTextureStorageMem2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESTORAGEMEM2DEXTPROC);
#define glTextureStorageMem2DMultisampleEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESTORAGEMEM2DMULTISAMPLEEXTPROC);
#define glTextureStorageMem3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESTORAGEMEM3DEXTPROC);
#define glTextureStorageMem3DMultisampleEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESTORAGEMEM3DMULTISAMPLEEXTPROC);
#define glTextureStorageSparseAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESTORAGESPARSEAMDPROC);
#define glTextureSubImage1D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESUBIMAGE1DPROC);
#define glTextureSubImage1DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESUBIMAGE1DEXTPROC);
#define glTextureSubImage2D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESUBIMAGE2DPROC);
#define glTextureSubImage2DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESUBIMAGE2DEXTPROC);
#define glTextureSubImage3D(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESUBIMAGE3DPROC);
#define glTextureSubImage3DEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTURESUBIMAGE3DEXTPROC);
#define glTextureView(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTEXTUREVIEWPROC);
#define glTrackMatrixNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTRACKMATRIXNVPROC);
#define glTransformFeedbackAttribsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTRANSFORMFEEDBACKATTRIBSNVPROC);
#define glTransformFeedbackBufferBase(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTRANSFORMFEEDBACKBUFFERBASEPROC);
#define glTransformFeedbackBufferRange(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTRANSFORMFEEDBACKBUFFERRANGEPROC);
#define glTransformFeedbackStreamAttribsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTRANSFORMFEEDBACKSTREAMATTRIBSNVPROC);
#define glTransformFeedbackVaryings(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTRANSFORMFEEDBACKVARYINGSPROC);
#define glTransformFeedbackVaryingsEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTRANSFORMFEEDBACKVARYINGSEXTPROC);
#define glTransformFeedbackVaryingsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTRANSFORMFEEDBACKVARYINGSNVPROC);
#define glTransformPathNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTRANSFORMPATHNVPROC);
#define glTranslated(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTRANSLATEDPROC);
#define glTranslatef(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTRANSLATEFPROC);
#define glTranslatexOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLTRANSLATEXOESPROC);
#define glUniform1d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1DPROC);
#define glUniform1dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1DVPROC);
#define glUniform1f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1FPROC);
#define glUniform1fARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1FARBPROC);
#define glUniform1fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1FVPROC);
#define glUniform1fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1FVARBPROC);
#define glUniform1i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1IPROC);
#define glUniform1i64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1I64ARBPROC);
#define glUniform1i64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1I64NVPROC);
#define glUniform1i64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1I64VARBPROC);
#define glUniform1i64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1I64VNVPROC);
#define glUniform1iARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1IARBPROC);
#define glUniform1iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1IVPROC);
#define glUniform1ivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1IVARBPROC);
#define glUniform1ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1UIPROC);
#define glUniform1ui64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1UI64ARBPROC);
#define glUniform1ui64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1UI64NVPROC);
#define glUniform1ui64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1UI64VARBPROC);
#define glUniform1ui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1UI64VNVPROC);
#define glUniform1uiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1UIEXTPROC);
#define glUniform1uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1UIVPROC);
#define glUniform1uivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM1UIVEXTPROC);
#define glUniform2d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2DPROC);
#define glUniform2dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2DVPROC);
#define glUniform2f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2FPROC);
#define glUniform2fARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2FARBPROC);
#define glUniform2fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2FVPROC);
#define glUniform2fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2FVARBPROC);
#define glUniform2i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2IPROC);
#define glUniform2i64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2I64ARBPROC);
#define glUniform2i64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2I64NVPROC);
#define glUniform2i64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2I64VARBPROC);
#define glUniform2i64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2I64VNVPROC);
#define glUniform2iARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2IARBPROC);
#define glUniform2iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2IVPROC);
#define glUniform2ivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2IVARBPROC);
#define glUniform2ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2UIPROC);
#define glUniform2ui64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2UI64ARBPROC);
#define glUniform2ui64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2UI64NVPROC);
#define glUniform2ui64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2UI64VARBPROC);
#define glUniform2ui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2UI64VNVPROC);
#define glUniform2uiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2UIEXTPROC);
#define glUniform2uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2UIVPROC);
#define glUniform2uivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM2UIVEXTPROC);
#define glUniform3d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3DPROC);
#define glUniform3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3DVPROC);
#define glUniform3f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3FPROC);
#define glUniform3fARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3FARBPROC);
#define glUniform3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3FVPROC);
#define glUniform3fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3FVARBPROC);
#define glUniform3i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3IPROC);
#define glUniform3i64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3I64ARBPROC);
#define glUniform3i64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3I64NVPROC);
#define glUniform3i64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3I64VARBPROC);
#define glUniform3i64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3I64VNVPROC);
#define glUniform3iARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3IARBPROC);
#define glUniform3iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3IVPROC);
#define glUniform3ivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3IVARBPROC);
#define glUniform3ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3UIPROC);
#define glUniform3ui64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3UI64ARBPROC);
#define glUniform3ui64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3UI64NVPROC);
#define glUniform3ui64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3UI64VARBPROC);
#define glUniform3ui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3UI64VNVPROC);
#define glUniform3uiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3UIEXTPROC);
#define glUniform3uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3UIVPROC);
#define glUniform3uivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM3UIVEXTPROC);
#define glUniform4d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4DPROC);
#define glUniform4dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4DVPROC);
#define glUniform4f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4FPROC);
#define glUniform4fARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4FARBPROC);
#define glUniform4fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4FVPROC);
#define glUniform4fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4FVARBPROC);
#define glUniform4i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4IPROC);
#define glUniform4i64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4I64ARBPROC);
#define glUniform4i64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4I64NVPROC);
#define glUniform4i64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4I64VARBPROC);
#define glUniform4i64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4I64VNVPROC);
#define glUniform4iARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4IARBPROC);
#define glUniform4iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4IVPROC);
#define glUniform4ivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4IVARBPROC);
#define glUniform4ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4UIPROC);
#define glUniform4ui64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4UI64ARBPROC);
#define glUniform4ui64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4UI64NVPROC);
#define glUniform4ui64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4UI64VARBPROC);
#define glUniform4ui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4UI64VNVPROC);
#define glUniform4uiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4UIEXTPROC);
#define glUniform4uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4UIVPROC);
#define glUniform4uivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORM4UIVEXTPROC);
#define glUniformBlockBinding(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMBLOCKBINDINGPROC);
#define glUniformBufferEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMBUFFEREXTPROC);
#define glUniformHandleui64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMHANDLEUI64ARBPROC);
#define glUniformHandleui64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMHANDLEUI64NVPROC);
#define glUniformHandleui64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMHANDLEUI64VARBPROC);
#define glUniformHandleui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMHANDLEUI64VNVPROC);
#define glUniformMatrix2dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX2DVPROC);
#define glUniformMatrix2fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX2FVPROC);
#define glUniformMatrix2fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX2FVARBPROC);
#define glUniformMatrix2x3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX2X3DVPROC);
#define glUniformMatrix2x3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX2X3FVPROC);
#define glUniformMatrix2x4dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX2X4DVPROC);
#define glUniformMatrix2x4fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX2X4FVPROC);
#define glUniformMatrix3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX3DVPROC);
#define glUniformMatrix3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX3FVPROC);
#define glUniformMatrix3fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX3FVARBPROC);
#define glUniformMatrix3x2dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX3X2DVPROC);
#define glUniformMatrix3x2fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX3X2FVPROC);
#define glUniformMatrix3x4dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX3X4DVPROC);
#define glUniformMatrix3x4fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX3X4FVPROC);
#define glUniformMatrix4dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX4DVPROC);
#define glUniformMatrix4fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX4FVPROC);
#define glUniformMatrix4fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX4FVARBPROC);
#define glUniformMatrix4x2dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX4X2DVPROC);
#define glUniformMatrix4x2fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX4X2FVPROC);
#define glUniformMatrix4x3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX4X3DVPROC);
#define glUniformMatrix4x3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMMATRIX4X3FVPROC);
#define glUniformSubroutinesuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMSUBROUTINESUIVPROC);
#define glUniformui64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMUI64NVPROC);
#define glUniformui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNIFORMUI64VNVPROC);
#define glUnlockArraysEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNLOCKARRAYSEXTPROC);
#define glUnmapBuffer(...) (0)
typedef JELLO_GRADER_PROC(PFNGLUNMAPBUFFERPROC);
#define glUnmapBufferARB(...) (0)
typedef JELLO_GRADER_PROC(PFNGLUNMAPBUFFERARBPROC);
#define glUnmapNamedBuffer(...) (0)
typedef JELLO_GRADER_PROC(PFNGLUNMAPNAMEDBUFFERPROC);
#define glUnmapNamedBufferEXT(...) (0)
typedef JELLO_GRADER_PROC(PFNGLUNMAPNAMEDBUFFEREXTPROC);
#define glUnmapObjectBufferATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNMAPOBJECTBUFFERATIPROC);
#define glUnmapTexture2DINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUNMAPTEXTURE2DINTELPROC);
#define glUpdateObjectBufferATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUPDATEOBJECTBUFFERATIPROC);
#define glUploadGpuMaskNVX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUPLOADGPUMASKNVXPROC);
#define glUseProgram(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUSEPROGRAMPROC);
#define glUseProgramObjectARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUSEPROGRAMOBJECTARBPROC);
#define glUseProgramStages(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUSEPROGRAMSTAGESPROC);
#define glUseShaderProgramEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLUSESHADERPROGRAMEXTPROC);
#define glVDPAUFiniNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVDPAUFININVPROC);
#define glVDPAUGetSurfaceivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVDPAUGETSURFACEIVNVPROC);
#define glVDPAUInitNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVDPAUINITNVPROC);
#define glVDPAUIsSurfaceNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLVDPAUISSURFACENVPROC);
#define glVDPAUMapSurfacesNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVDPAUMAPSURFACESNVPROC);
#define glVDPAURegisterOutputSurfaceNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLVDPAUREGISTEROUTPUTSURFACENVPROC);
#define glVDPAURegisterVideoSurfaceNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLVDPAUREGISTERVIDEOSURFACENVPROC);
#define glVDPAURegisterVideoSurfaceWithPictureStructureNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLVDPAUREGISTERVIDEOSURFACEWITHPICTURESTRUCTURENVPROC);
#define glVDPAUSurfaceAccessNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVDPAUSURFACEACCESSNVPROC);
#define glVDPAUUnmapSurfacesNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVDPAUUNMAPSURFACESNVPROC);
#define glVDPAUUnregisterSurfaceNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVDPAUUNREGISTERSURFACENVPROC);
#define glValidateProgram(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVALIDATEPROGRAMPROC);
#define glValidateProgramARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVALIDATEPROGRAMARBPROC);
#define glValidateProgramPipeline(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVALIDATEPROGRAMPIPELINEPROC);
#define glVariantArrayObjectATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVARIANTARRAYOBJECTATIPROC);
#define glVariantPointerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVARIANTPOINTEREXTPROC);
#define glVariantbvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVARIANTBVEXTPROC);
#define glVariantdvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVARIANTDVEXTPROC);
#define glVariantfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVARIANTFVEXTPROC);
#define glVariantivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVARIANTIVEXTPROC);
#define glVariantsvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVARIANTSVEXTPROC);
#define glVariantubvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVARIANTUBVEXTPROC);
#define glVariantuivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVARIANTUIVEXTPROC);
#define glVariantusvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVARIANTUSVEXTPROC);
#define glVertex2bOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX2BOESPROC);
#define glVertex2bvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX2BVOESPROC);
#define glVertex2d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX2DPROC);
#define glVertex2dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX2DVPROC);
#define glVertex2f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX2FPROC);
#define glVertex2fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX2FVPROC);
#define glVertex2hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX2HNVPROC);
#define glVertex2hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX2HVNVPROC);
#define glVertex2i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX2IPROC);
#define glVertex2iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX2IVPROC);
#define glVertex2s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX2SPROC);
#define glVertex2sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX2SVPROC);
#define glVertex2xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX2XOESPROC);
#define glVertex2xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX2XVOESPROC);
#define glVertex3bOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX3BOESPROC);
#define glVertex3bvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX3BVOESPROC);
#define glVertex3d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX3DPROC);
#define glVertex3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX3DVPROC);
#define glVertex3f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX3FPROC);
#define glVertex3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX3FVPROC);
#define glVertex3hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX3HNVPROC);
#define glVertex3hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX3HVNVPROC);
#define glVertex3i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX3IPROC);
#define glVertex3iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX3IVPROC);
#define glVertex3s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX3SPROC);
#define glVertex3sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX3SVPROC);
#define glVertex3xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX3XOESPROC);
#define glVertex3xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX3XVOESPROC);
#define glVertex4bOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX4BOESPROC);
#define glVertex4bvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX4BVOESPROC);
#define glVertex4d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX4DPROC);
#define glVertex4dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX4DVPROC);
#define glVertex4f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX4FPROC);
#define glVertex4fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX4FVPROC);
#define glVertex4hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX4HNVPROC);
#define glVertex4hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX4HVNVPROC);
#define glVertex4i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX4IPROC);
#define glVertex4iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX4IVPROC);
#define glVertex4s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX4SPROC);
#define glVertex4sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX4SVPROC);
#define glVertex4xOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX4XOESPROC);
#define glVertex4xvOES(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEX4XVOESPROC);
#define glVertexArrayAttribBinding(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYATTRIBBINDINGPROC);
#define glVertexArrayAttribFormat(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYATTRIBFORMATPROC);
#define glVertexArrayAttribIFormat(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYATTRIBIFORMATPROC);
#define glVertexArrayAttribLFormat(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYATTRIBLFORMATPROC);
#define glVertexArrayBindVertexBufferEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYBINDVERTEXBUFFEREXTPROC);
#define glVertexArrayBindingDivisor(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYBINDINGDIVISORPROC);
#define glVertexArrayColorOffsetEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYCOLOROFFSETEXTPROC);
#define glVertexArrayEdgeFlagOffsetEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYEDGEFLAGOFFSETEXTPROC);
#define glVertexArrayElementBuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYELEMENTBUFFERPROC);
#define glVertexArrayFogCoordOffsetEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYFOGCOORDOFFSETEXTPROC);
#define glVertexArrayIndexOffsetEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYINDEXOFFSETEXTPROC);
#define glVertexArrayMultiTexCoordOffsetEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYMULTITEXCOORDOFFSETEXTPROC);
#define glVertexArrayNormalOffsetEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYNORMALOFFSETEXTPROC);
#define glVertexArrayParameteriAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYPARAMETERIAPPLEPROC);
#define glVertexArrayRangeAPPLE(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYRANGEAPPLEPROC);
#define glVertexArrayRangeNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYRANGENVPROC);
#define glVertexArraySecondaryColorOffsetEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYSECONDARYCOLOROFFSETEXTPROC);
#define glVertexArrayTexCoordOffsetEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYTEXCOORDOFFSETEXTPROC);
#define glVertexArrayVertexAttribBindingEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYVERTEXATTRIBBINDINGEXTPROC);
#define glVertexArrayVertexAttribDivisorEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYVERTEXATTRIBDIVISOREXTPROC);
#define glVertexArrayVertexAttribFormatEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYVERTEXATTRIBFORMATEXTPROC);
#define glVertexArrayVertexAttribIFormatEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYVERTEXATTRIBIFORMATEXTPROC);
#define glVertexArrayVertexAttribIOffsetEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYVERTEXATTRIBIOFFSETEXTPROC);
#define glVertexArrayVertexAttribLFormatEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYVERTEXATTRIBLFORMATEXTPROC);
#define glVertexArrayVertexAttribLOffsetEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYVERTEXATTRIBLOFFSETEXTPROC);
#define glVertexArrayVertexAttribOffsetEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYVERTEXATTRIBOFFSETEXTPROC);
#define glVertexArrayVertexBindingDivisorEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYVERTEXBINDINGDIVISOREXTPROC);
#define glVertexArrayVertexBuffer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYVERTEXBUFFERPROC);
#define glVertexArrayVertexBuffers(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYVERTEXBUFFERSPROC);
#define glVertexArrayVertexOffsetEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXARRAYVERTEXOFFSETEXTPROC);
#define glVertexAttrib1d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1DPROC);
#define glVertexAttrib1dARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1DARBPROC);
#define glVertexAttrib1dNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1DNVPROC);
#define glVertexAttrib1dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1DVPROC);
#define glVertexAttrib1dvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1DVARBPROC);
#define glVertexAttrib1dvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1DVNVPROC);
#define glVertexAttrib1f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1FPROC);
#define glVertexAttrib1fARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1FARBPROC);
#define glVertexAttrib1fNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1FNVPROC);
#define glVertexAttrib1fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1FVPROC);
#define glVertexAttrib1fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1FVARBPROC);
#define glVertexAttrib1fvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1FVNVPROC);
#define glVertexAttrib1hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1HNVPROC);
#define glVertexAttrib1hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1HVNVPROC);
#define glVertexAttrib1s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1SPROC);
#define glVertexAttrib1sARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1SARBPROC);
#define glVertexAttrib1sNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1SNVPROC);
#define glVertexAttrib1sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1SVPROC);
#define glVertexAttrib1svARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1SVARBPROC);
#define glVertexAttrib1svNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB1SVNVPROC);
#define glVertexAttrib2d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2DPROC);
#define glVertexAttrib2dARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2DARBPROC);
#define glVertexAttrib2dNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2DNVPROC);
#define glVertexAttrib2dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2DVPROC);
#define glVertexAttrib2dvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2DVARBPROC);
#define glVertexAttrib2dvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2DVNVPROC);
#define glVertexAttrib2f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2FPROC);
#define glVertexAttrib2fARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2FARBPROC);
#define glVertexAttrib2fNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2FNVPROC);
#define glVertexAttrib2fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2FVPROC);
#define glVertexAttrib2fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2FVARBPROC);
#define glVertexAttrib2fvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2FVNVPROC);
#define glVertexAttrib2hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2HNVPROC);
#define glVertexAttrib2hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2HVNVPROC);
#define glVertexAttrib2s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2SPROC);
#define glVertexAttrib2sARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2SARBPROC);
#define glVertexAttrib2sNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2SNVPROC);
#define glVertexAttrib2sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2SVPROC);
#define glVertexAttrib2svARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2SVARBPROC);
#define glVertexAttrib2svNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB2SVNVPROC);
#define glVertexAttrib3d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3DPROC);
#define glVertexAttrib3dARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3DARBPROC);
#define glVertexAttrib3dNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3DNVPROC);
#define glVertexAttrib3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3DVPROC);
#define glVertexAttrib3dvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3DVARBPROC);
#define glVertexAttrib3dvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3DVNVPROC);
#define glVertexAttrib3f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3FPROC);
#define glVertexAttrib3fARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3FARBPROC);
#define glVertexAttrib3fNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3FNVPROC);
#define glVertexAttrib3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3FVPROC);
#define glVertexAttrib3fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3FVARBPROC);
#define glVertexAttrib3fvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3FVNVPROC);
#define glVertexAttrib3hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3HNVPROC);
#define glVertexAttrib3hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3HVNVPROC);
#define glVertexAttrib3s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3SPROC);
#define glVertexAttrib3sARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3SARBPROC);
#define glVertexAttrib3sNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3SNVPROC);
#define glVertexAttrib3sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3SVPROC);
#define glVertexAttrib3svARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3SVARBPROC);
#define glVertexAttrib3svNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB3SVNVPROC);
#define glVertexAttrib4Nbv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4NBVPROC);
#define glVertexAttrib4NbvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4NBVARBPROC);
#define glVertexAttrib4Niv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4NIVPROC);
#define glVertexAttrib4NivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4NIVARBPROC);
#define glVertexAttrib4Nsv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4NSVPROC);
#define glVertexAttrib4NsvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4NSVARBPROC);
#define glVertexAttrib4Nub(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4NUBPROC);
#define glVertexAttrib4NubARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4NUBARBPROC);
#define glVertexAttrib4Nubv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4NUBVPROC);
#define glVertexAttrib4NubvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4NUBVARBPROC);
#define glVertexAttrib4Nuiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4NUIVPROC);
#define glVertexAttrib4NuivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4NUIVARBPROC);
#define glVertexAttrib4Nusv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4NUSVPROC);
#define glVertexAttrib4NusvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4NUSVARBPROC);
#define glVertexAttrib4bv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4BVPROC);
#define glVertexAttrib4bvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4BVARBPROC);
#define glVertexAttrib4d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4DPROC);
#define glVertexAttrib4dARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4DARBPROC);
#define glVertexAttrib4dNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4DNVPROC);
#define glVertexAttrib4dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4DVPROC);
#define glVertexAttrib4dvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4DVARBPROC);
#define glVertexAttrib4dvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4DVNVPROC);
#define glVertexAttrib4f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4FPROC);
#define glVertexAttrib4fARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4FARBPROC);
#define glVertexAttrib4fNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4FNVPROC);
#define glVertexAttrib4fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4FVPROC);
#define glVertexAttrib4fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4FVARBPROC);
#define glVertexAttrib4fvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4FVNVPROC);
#define glVertexAttrib4hNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4HNVPROC);
#define glVertexAttrib4hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4HVNVPROC);
#define glVertexAttrib4iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4IVPROC);
#define glVertexAttrib4ivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4IVARBPROC);
#define glVertexAttrib4s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4SPROC);
#define glVertexAttrib4sARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4SARBPROC);
#define glVertexAttrib4sNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4SNVPROC);
#define glVertexAttrib4sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4SVPROC);
#define glVertexAttrib4svARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4SVARBPROC);
#define glVertexAttrib4svNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4SVNVPROC);
#define glVertexAttrib4ubNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4UBNVPROC);
#define glVertexAttrib4ubv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4UBVPROC);
#define glVertexAttrib4ubvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4UBVARBPROC);
#define glVertexAttrib4ubvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4UBVNVPROC);
#define glVertexAttrib4uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4UIVPROC);
#define glVertexAttrib4uivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4UIVARBPROC);
#define glVertexAttrib4usv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4USVPROC);
#define glVertexAttrib4usvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIB4USVARBPROC);
#define glVertexAttribArrayObjectATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBARRAYOBJECTATIPROC);
#define glVertexAttribBinding(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBBINDINGPROC);
#define glVertexAttribDivisor(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBDIVISORPROC);
#define glVertexAttribDivisorARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBDIVISORARBPROC);
#define glVertexAttribFormat(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBFORMATPROC);
#define glVertexAttribFormatNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBFORMATNVPROC);
#define glVertexAttribI1i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI1IPROC);
#define glVertexAttribI1iEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI1IEXTPROC);
#define glVertexAttribI1iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI1IVPROC);
#define glVertexAttribI1ivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI1IVEXTPROC);
#define glVertexAttribI1ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI1UIPROC);
#define glVertexAttribI1uiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI1UIEXTPROC);
#define glVertexAttribI1uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI1UIVPROC);
#define glVertexAttribI1uivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI1UIVEXTPROC);
#define glVertexAttribI2i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI2IPROC);
#define glVertexAttribI2iEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI2IEXTPROC);
#define glVertexAttribI2iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI2IVPROC);
#define glVertexAttribI2ivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI2IVEXTPROC);
#define glVertexAttribI2ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI2UIPROC);
#define glVertexAttribI2uiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI2UIEXTPROC);
#define glVertexAttribI2uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI2UIVPROC);
#define glVertexAttribI2uivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI2UIVEXTPROC);
#define glVertexAttribI3i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI3IPROC);
#define glVertexAttribI3iEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI3IEXTPROC);
#define glVertexAttribI3iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI3IVPROC);
#define glVertexAttribI3ivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI3IVEXTPROC);
#define glVertexAttribI3ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI3UIPROC);
#define glVertexAttribI3uiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI3UIEXTPROC);
#define glVertexAttribI3uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI3UIVPROC);
#define glVertexAttribI3uivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI3UIVEXTPROC);
#define glVertexAttribI4bv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI4BVPROC);
#define glVertexAttribI4bvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI4BVEXTPROC);
#define glVertexAttribI4i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI4IPROC);
#define glVertexAttribI4iEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI4IEXTPROC);
#define glVertexAttribI4iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI4IVPROC);
#define glVertexAttribI4ivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI4IVEXTPROC);
#define glVertexAttribI4sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI4SVPROC);
#define glVertexAttribI4svEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI4SVEXTPROC);
#define glVertexAttribI4ubv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI4UBVPROC);
#define glVertexAttribI4ubvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI4UBVEXTPROC);
#define glVertexAttribI4ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI4UIPROC);
#define glVertexAttribI4uiEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI4UIEXTPROC);
#define glVertexAttribI4uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI4UIVPROC);
#define glVertexAttribI4uivEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI4UIVEXTPROC);
#define glVertexAttribI4usv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI4USVPROC);
#define glVertexAttribI4usvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBI4USVEXTPROC);
#define glVertexAttribIFormat(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBIFORMATPROC);
#define glVertexAttribIFormatNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBIFORMATNVPROC);
#define glVertexAttribIPointer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBIPOINTERPROC);
#define glVertexAttribIPointerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBIPOINTEREXTPROC);
#define glVertexAttribL1d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL1DPROC);
#define glVertexAttribL1dEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL1DEXTPROC);
#define glVertexAttribL1dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL1DVPROC);
#define glVertexAttribL1dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL1DVEXTPROC);
#define glVertexAttribL1i64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL1I64NVPROC);
#define glVertexAttribL1i64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL1I64VNVPROC);
#define glVertexAttribL1ui64ARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL1UI64ARBPROC);
#define glVertexAttribL1ui64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL1UI64NVPROC);
#define glVertexAttribL1ui64vARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL1UI64VARBPROC);
#define glVertexAttribL1ui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL1UI64VNVPROC);
#define glVertexAttribL2d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL2DPROC);
#define glVertexAttribL2dEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL2DEXTPROC);
#define glVertexAttribL2dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL2DVPROC);
#define glVertexAttribL2dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL2DVEXTPROC);
#define glVertexAttribL2i64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL2I64NVPROC);
#define glVertexAttribL2i64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL2I64VNVPROC);
#define glVertexAttribL2ui64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL2UI64NVPROC);
#define glVertexAttribL2ui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL2UI64VNVPROC);
#define glVertexAttribL3d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL3DPROC);
#define glVertexAttribL3dEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL3DEXTPROC);
#define glVertexAttribL3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL3DVPROC);
#define glVertexAttribL3dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL3DVEXTPROC);
#define glVertexAttribL3i64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL3I64NVPROC);
#define glVertexAttribL3i64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL3I64VNVPROC);
#define glVertexAttribL3ui64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL3UI64NVPROC);
#define glVertexAttribL3ui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL3UI64VNVPROC);
#define glVertexAttribL4d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL4DPROC);
#define glVertexAttribL4dEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL4DEXTPROC);
#define glVertexAttribL4dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL4DVPROC);
#define glVertexAttribL4dvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL4DVEXTPROC);
#define glVertexAttribL4i64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL4I64NVPROC);
#define glVertexAttribL4i64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL4I64VNVPROC);
#define glVertexAttribL4ui64NV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL4UI64NVPROC);
#define glVertexAttribL4ui64vNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBL4UI64VNVPROC);
#define glVertexAttribLFormat(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBLFORMATPROC);
#define glVertexAttribLFormatNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBLFORMATNVPROC);
#define glVertexAttribLPointer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBLPOINTERPROC);
#define glVertexAttribLPointerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBLPOINTEREXTPROC);
#define glVertexAttribP1ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBP1UIPROC);
#define glVertexAttribP1uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBP1UIVPROC);
#define glVertexAttribP2ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBP2UIPROC);
#define glVertexAttribP2uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBP2UIVPROC);
#define glVertexAttribP3ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBP3UIPROC);
#define glVertexAttribP3uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBP3UIVPROC);
#define glVertexAttribP4ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBP4UIPROC);
#define glVertexAttribP4uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBP4UIVPROC);
#define glVertexAttribParameteriAMD(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBPARAMETERIAMDPROC);
#define glVertexAttribPointer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBPOINTERPROC);
#define glVertexAttribPointerARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBPOINTERARBPROC);
#define glVertexAttribPointerNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBPOINTERNVPROC);
#define glVertexAttribs1dvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS1DVNVPROC);
#define glVertexAttribs1fvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS1FVNVPROC);
#define glVertexAttribs1hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS1HVNVPROC);
#define glVertexAttribs1svNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS1SVNVPROC);
#define glVertexAttribs2dvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS2DVNVPROC);
#define glVertexAttribs2fvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS2FVNVPROC);
#define glVertexAttribs2hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS2HVNVPROC);
#define glVertexAttribs2svNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS2SVNVPROC);
#define glVertexAttribs3dvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS3DVNVPROC);
#define glVertexAttribs3fvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS3FVNVPROC);
#define glVertexAttribs3hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS3HVNVPROC);
#define glVertexAttribs3svNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS3SVNVPROC);
#define glVertexAttribs4dvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS4DVNVPROC);
#define glVertexAttribs4fvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS4FVNVPROC);
#define glVertexAttribs4hvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS4HVNVPROC);
#define glVertexAttribs4svNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS4SVNVPROC);
#define glVertexAttribs4ubvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXATTRIBS4UBVNVPROC);
#define glVertexBindingDivisor(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXBINDINGDIVISORPROC);
#define glVertexBlendARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXBLENDARBPROC);
#define glVertexBlendEnvfATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXBLENDENVFATIPROC);
#define glVertexBlendEnviATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXBLENDENVIATIPROC);
#define glVertexFormatNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXFORMATNVPROC);
#define glVertexP2ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXP2UIPROC);
#define glVertexP2uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXP2UIVPROC);
#define glVertexP3ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXP3UIPROC);
#define glVertexP3uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXP3UIVPROC);
#define glVertexP4ui(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXP4UIPROC);
#define glVertexP4uiv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXP4UIVPROC);
#define glVertexPointer(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXPOINTERPROC);
#define glVertexPointerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXPOINTEREXTPROC);
#define glVertexPointerListIBM(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXPOINTERLISTIBMPROC);
#define glVertexPointervINTEL(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXPOINTERVINTELPROC);
#define glVertexStream1dATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM1DATIPROC);
#define glVertexStream1dvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM1DVATIPROC);
#define glVertexStream1fATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM1FATIPROC);
#define glVertexStream1fvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM1FVATIPROC);
#define glVertexStream1iATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM1IATIPROC);
#define glVertexStream1ivATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM1IVATIPROC);
#define glVertexStream1sATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM1SATIPROC);
#define glVertexStream1svATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM1SVATIPROC);
#define glVertexStream2dATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM2DATIPROC);
#define glVertexStream2dvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM2DVATIPROC);
#define glVertexStream2fATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM2FATIPROC);
#define glVertexStream2fvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM2FVATIPROC);
#define glVertexStream2iATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM2IATIPROC);
#define glVertexStream2ivATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM2IVATIPROC);
#define glVertexStream2sATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM2SATIPROC);
#define glVertexStream2svATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM2SVATIPROC);
#define glVertexStream3dATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM3DATIPROC);
#define glVertexStream3dvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM3DVATIPROC);
#define glVertexStream3fATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM3FATIPROC);
#define glVertexStream3fvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM3FVATIPROC);
#define glVertexStream3iATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM3IATIPROC);
#define glVertexStream3ivATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM3IVATIPROC);
#define glVertexStream3sATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM3SATIPROC);
#define glVertexStream3svATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM3SVATIPROC);
#define glVertexStream4dATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM4DATIPROC);
#define glVertexStream4dvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM4DVATIPROC);
#define glVertexStream4fATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM4FATIPROC);
#define glVertexStream4fvATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM4FVATIPROC);
#define glVertexStream4iATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM4IATIPROC);
#define glVertexStream4ivATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM4IVATIPROC);
#define glVertexStream4sATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM4SATIPROC);
#define glVertexStream4svATI(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXSTREAM4SVATIPROC);
#define glVertexWeightPointerEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXWEIGHTPOINTEREXTPROC);
#define glVertexWeightfEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXWEIGHTFEXTPROC);
#define glVertexWeightfvEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXWEIGHTFVEXTPROC);
#define glVertexWeighthNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXWEIGHTHNVPROC);
#define glVertexWeighthvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVERTEXWEIGHTHVNVPROC);
#define glVideoCaptureNV(...) (0)
typedef JELLO_GRADER_PROC(PFNGLVIDEOCAPTURENVPROC);
#define glVideoCaptureStreamParameterdvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVIDEOCAPTURESTREAMPARAMETERDVNVPROC);
#define glVideoCaptureStreamParameterfvNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVIDEOCAPTURESTREAMPARAMETERFVNVPROC);
#define glVideoCaptureStreamParameterivNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVIDEOCAPTURESTREAMPARAMETERIVNVPROC);
#define glViewport(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVIEWPORTPROC);
#define glViewportArrayv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVIEWPORTARRAYVPROC);
#define glViewportIndexedf(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVIEWPORTINDEXEDFPROC);
#define glViewportIndexedfv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVIEWPORTINDEXEDFVPROC);
#define glViewportPositionWScaleNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVIEWPORTPOSITIONWSCALENVPROC);
#define glViewportSwizzleNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLVIEWPORTSWIZZLENVPROC);
#define glWaitSemaphoreEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWAITSEMAPHOREEXTPROC);
#define glWaitSemaphoreui64NVX(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWAITSEMAPHOREUI64NVXPROC);
#define glWaitSync(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWAITSYNCPROC);
#define glWaitVkSemaphoreNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWAITVKSEMAPHORENVPROC);
#define glWeightPathsNV(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWEIGHTPATHSNVPROC);
#define glWeightPointerARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWEIGHTPOINTERARBPROC);
#define glWeightbvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWEIGHTBVARBPROC);
#define glWeightdvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWEIGHTDVARBPROC);
#define glWeightfvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWEIGHTFVARBPROC);
#define glWeightivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWEIGHTIVARBPROC);
#define glWeightsvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWEIGHTSVARBPROC);
#define glWeightubvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWEIGHTUBVARBPROC);
#define glWeightuivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWEIGHTUIVARBPROC);
#define glWeightusvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWEIGHTUSVARBPROC);
#define glWindowPos2d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2DPROC);
#define glWindowPos2dARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2DARBPROC);
#define glWindowPos2dMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2DMESAPROC);
#define glWindowPos2dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2DVPROC);
#define glWindowPos2dvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2DVARBPROC);
#define glWindowPos2dvMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2DVMESAPROC);
#define glWindowPos2f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2FPROC);
#define glWindowPos2fARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2FARBPROC);
#define glWindowPos2fMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2FMESAPROC);
#define glWindowPos2fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2FVPROC);
#define glWindowPos2fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2FVARBPROC);
#define glWindowPos2fvMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2FVMESAPROC);
#define glWindowPos2i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2IPROC);
#define glWindowPos2iARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2IARBPROC);
#define glWindowPos2iMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2IMESAPROC);
#define glWindowPos2iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2IVPROC);
#define glWindowPos2ivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2IVARBPROC);
#define glWindowPos2ivMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2IVMESAPROC);
#define glWindowPos2s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2SPROC);
#define glWindowPos2sARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2SARBPROC);
#define glWindowPos2sMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2SMESAPROC);
#define glWindowPos2sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2SVPROC);
#define glWindowPos2svARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2SVARBPROC);
#define glWindowPos2svMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS2SVMESAPROC);
#define glWindowPos3d(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3DPROC);
#define glWindowPos3dARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3DARBPROC);
#define glWindowPos3dMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3DMESAPROC);
#define glWindowPos3dv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3DVPROC);
#define glWindowPos3dvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3DVARBPROC);
#define glWindowPos3dvMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3DVMESAPROC);
#define glWindowPos3f(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3FPROC);
#define glWindowPos3fARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3FARBPROC);
#define glWindowPos3fMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3FMESAPROC);
#define glWindowPos3fv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3FVPROC);
#define glWindowPos3fvARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3FVARBPROC);
#define glWindowPos3fvMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3FVMESAPROC);
#define glWindowPos3i(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3IPROC);
#define glWindowPos3iARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3IARBPROC);
#define glWindowPos3iMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3IMESAPROC);
#define glWindowPos3iv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3IVPROC);
#define glWindowPos3ivARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3IVARBPROC);
#define glWindowPos3ivMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3IVMESAPROC);
#define glWindowPos3s(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3SPROC);
#define glWindowPos3sARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3SARBPROC);
#define glWindowPos3sMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3SMESAPROC);
#define glWindowPos3sv(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3SVPROC);
#define glWindowPos3svARB(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3SVARBPROC);
#define glWindowPos3svMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS3SVMESAPROC);
#define glWindowPos4dMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS4DMESAPROC);
#define glWindowPos4dvMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS4DVMESAPROC);
#define glWindowPos4fMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS4FMESAPROC);
#define glWindowPos4fvMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS4FVMESAPROC);
#define glWindowPos4iMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS4IMESAPROC);
#define glWindowPos4ivMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS4IVMESAPROC);
#define glWindowPos4sMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS4SMESAPROC);
#define glWindowPos4svMESA(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWPOS4SVMESAPROC);
#define glWindowRectanglesEXT(...) ((void)0)
typedef JELLO_GRADER_PROC(PFNGLWINDOWRECTANGLESEXTPROC);
