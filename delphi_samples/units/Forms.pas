{ Forms.pas -- a headless stand-in for the VCL's Forms unit: just enough of
  TForm and TApplication for the book programs' event structure
  (FormCreate / FormResize / FormPaint / FormKeyPress / FormDestroy and
  Application.OnIdle), with no window system.

  A form's client area is an offscreen device context (unit Windows);
  Width and Height are the outer size of a classic sizeable Windows frame
  (4 px border each side, 19 px caption), because the book programs pass
  Width/Height, not ClientWidth/ClientHeight, to glViewport
  (seeds-inventory §3.1 quirk 5): the viewport is then larger than the
  drawable, as on Windows.

  The program file drives the form the way a user would: Show (resize and
  first paint), Paint, KeyPress, Idle, and Snapshot writes the frame last
  shown by SwapBuffers as a PNG into $DELPHI_OUT (default out/delphi). }
unit Forms;

{$mode delphi}

interface

uses Windows;

const
  FrameX = 8;    { 2 x 4 px border }
  FrameY = 27;   { 2 x 4 px border + 19 px caption }

type
  TComponent = class
    constructor Create(AOwner: TComponent); virtual;
  end;
  TNotifyEvent = procedure(Sender: TObject) of object;
  TKeyPressEvent = procedure(Sender: TObject; var Key: Char) of object;
  TCloseAction = (caNone, caHide, caFree, caMinimize);
  TCloseEvent = procedure(Sender: TObject; var Action: TCloseAction) of object;
  TIdleEvent = procedure(Sender: TObject; var Done: Boolean) of object;
  TMouseButton = (mbLeft, mbRight, mbMiddle);
  TShiftState = set of (ssShift, ssAlt, ssCtrl, ssLeft, ssRight, ssMiddle, ssDouble);
  TMouseEvent = procedure(Sender: TObject; Button: TMouseButton;
    Shift: TShiftState; X, Y: Integer) of object;
  TMouseMoveEvent = procedure(Sender: TObject; Shift: TShiftState; X, Y: Integer) of object;

  TForm = class(TComponent)
  private
    FHandle: HWND;
    function GetHandle: HWND;
    function GetWidth: Integer;
    function GetHeight: Integer;
  public
    ClientWidth, ClientHeight: Integer;   { what the .dfm would set }
    Caption: string;
    OnCreate, OnDestroy, OnPaint, OnResize: TNotifyEvent;
    OnKeyPress: TKeyPressEvent;
    OnClose: TCloseEvent;
    OnMouseDown, OnMouseUp: TMouseEvent;
    OnMouseMove: TMouseMoveEvent;
    { WM_PAINT without a message handler of the form's own: OnPaint }
    procedure DefaultHandler(var Message); override;
    property Handle: HWND read GetHandle;
    property Width: Integer read GetWidth;
    property Height: Integer read GetHeight;
  end;
  TFormClass = class of TForm;

  TApplication = class
  public
    MainForm: TForm;
    OnIdle: TIdleEvent;
    Title: string;
    procedure Initialize;
    procedure CreateForm(FormClass: TFormClass; var Reference);
    { headless driving, in place of the user and the message loop }
    procedure Show;
    procedure Paint;
    procedure KeyPress(Key: Char);
    procedure Idle;
    procedure Drag(X0, Y0, X1, Y1: Integer);
    procedure Terminate;
    function Snapshot(const Name: string): Boolean;
    function FrontImage(out W, H: Integer): PByte;
  end;

var
  Application: TApplication;

function OutDir: string;

implementation

uses SysUtils, Messages, PngFile;

function softglGetDCImage(dc: Pointer; w, h: PLongInt): PByte; stdcall; external 'GL';

constructor TComponent.Create(AOwner: TComponent);
begin
  inherited Create;
end;

function TForm.GetHandle: HWND;
begin
  if FHandle = 0 then FHandle := RegisterWindow(ClientWidth, ClientHeight);
  Result := FHandle;
end;

procedure TForm.DefaultHandler(var Message);
begin
  if (TMessage(Message).Msg = WM_PAINT) and Assigned(OnPaint) then OnPaint(Self);
end;

function TForm.GetWidth: Integer;
begin
  Result := ClientWidth + FrameX;
end;

function TForm.GetHeight: Integer;
begin
  Result := ClientHeight + FrameY;
end;

function OutDir: string;
begin
  Result := GetEnvironmentVariable('DELPHI_OUT');
  if Result = '' then Result := 'out/delphi';
end;

procedure TApplication.Initialize;
begin
end;

procedure TApplication.CreateForm(FormClass: TFormClass; var Reference);
var f: TForm;
begin
  f := FormClass.Create(nil);
  TForm(Reference) := f;
  if MainForm = nil then MainForm := f;
  if Assigned(f.OnCreate) then f.OnCreate(f);
end;

procedure TApplication.Show;
begin
  if Assigned(MainForm.OnResize) then MainForm.OnResize(MainForm);
  Paint;
end;

procedure TApplication.Paint;
var m: TWMPaint;
begin
  FillChar(m, SizeOf(m), 0);
  m.Msg := WM_PAINT;
  MainForm.Dispatch(m);    { a `message WM_PAINT` method, else OnPaint }
end;

procedure TApplication.KeyPress(Key: Char);
begin
  if Assigned(MainForm.OnKeyPress) then MainForm.OnKeyPress(MainForm, Key);
  Paint;   { the handlers call InvalidateRect: the repaint follows }
end;

procedure TApplication.Idle;
var done: Boolean;
begin
  done := True;
  if Assigned(OnIdle) then OnIdle(Self, done);
  Paint;
end;

{ a left-button drag from (X0,Y0) to (X1,Y1), client coordinates (y down),
  in one move; each mouse event repaints as the programs ask }
procedure TApplication.Drag(X0, Y0, X1, Y1: Integer);
begin
  if Assigned(MainForm.OnMouseDown) then MainForm.OnMouseDown(MainForm, mbLeft, [ssLeft], X0, Y0);
  if Assigned(MainForm.OnMouseMove) then MainForm.OnMouseMove(MainForm, [ssLeft], X1, Y1);
  if Assigned(MainForm.OnMouseUp) then MainForm.OnMouseUp(MainForm, mbLeft, [], X1, Y1);
  Paint;
end;

procedure TApplication.Terminate;
var action: TCloseAction;
begin
  action := caFree;
  if Assigned(MainForm.OnClose) then MainForm.OnClose(MainForm, action);
  if Assigned(MainForm.OnDestroy) then MainForm.OnDestroy(MainForm);
end;

function TApplication.FrontImage(out W, H: Integer): PByte;
var w32, h32: LongInt;
begin
  w32 := 0; h32 := 0;
  Result := softglGetDCImage(SoftglDC(WindowDC(MainForm.Handle)), @w32, @h32);
  W := w32; H := h32;
end;

function TApplication.Snapshot(const Name: string): Boolean;
var p: PByte; w, h: Integer; path: string;
begin
  p := FrontImage(w, h);
  path := IncludeTrailingPathDelimiter(OutDir) + Name + '.png';
  ForceDirectories(OutDir);
  Result := WritePNG(path, w, h, p);
  if Result then WriteLn('wrote ', path) else WriteLn('FAIL could not write ', path);
end;

initialization
  Application := TApplication.Create;
end.
